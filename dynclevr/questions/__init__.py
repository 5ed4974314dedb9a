"""The dataset's language half and the model's reasoning half (paper section 3.4 and appendix "Program execution").

- labels.py: per object and frame language labels (velocity class, moving direction, accelerating, floating) and
  the collision events, computed from a Scene4D's state arrays, so truth and estimate are labelled by one code path;
- programs.py: the paper's operations, one small typed function each, and the postfix-program executor;
- templates.json: the question families as data (paraphrases + program template each);
- generate.py: candidate questions per scene from its truth, and split-level answer balancing;
- tables.py: the Arrow schemas (name + version) of labels/, the per-scene candidates and questions.parquet.
"""
