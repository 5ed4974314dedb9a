"""NS-4DPhysics scene parser (REFERENCE.md section 2): video frames -> estimated 4D scene (Scene4D).

- features.py     the CNN feature extractor (stride 8, unit features) with a centre-heatmap / distance head
- neural_mesh.py  3D neural mesh models (one per sub-type) and the clutter (background) model
- render.py       the differentiable vertex-feature splatter: pose -> projected vertices -> rendering likelihood
- pose.py         render-and-compare pose optimisation with the physics prior
- detect.py       object proposals, sub-type by likelihood
- color.py        the colour classifier on the object's crop
- tracker.py      the causal filter over frames (single-particle Bayes filter with the physics engine)
- dynamics.py     velocity / acceleration / engine / floating from the estimated trajectory; collision events
- model.py        the trained parts together, saved to and loaded from weights/parser/
- train.py        `dynclevr train parser`
- evaluate.py     `dynclevr eval-parser`: the estimate against the truth
"""
