"""Table 1's baselines measured on our data: the CNN+LSTM (cnnlstm.py) and the per-frame 3D model in the manner of
PO3D-VQA (perframe.py). Each reads only what its model may: the video (RGB frames and calibration) and the
question text."""
