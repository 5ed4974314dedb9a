"""The question parser (question text -> program, an attention LSTM seq2seq model) and the blind baseline."""
