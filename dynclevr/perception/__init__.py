"""NS-4DPhysics scene parser (REFERENCE.md section 2): video frames -> estimated 4D scene (Scene4D).

The steps, in the order a frame meets them (DESIGN.md, "The scene parser"):
- detector.py        the detection head: per-cell centre heatmap, offset, sub-type, colour, yaw, distance, height
- detector_data.py   its training frames, made on demand by the generator (shards of rendered frames + targets)
- detector_train.py  `dynclevr train detector` (resumable), its held-out metrics, loading the shipped weights
- place.py           3D placement of a detection from the camera ray (ground plane, or distance for aeroplanes)
- tracker.py         association, the Kalman filter around the physics engine (the prior), refinement, collisions
- features.py        the CNN feature extractor (stride 8, unit features) of render-and-compare
- neural_mesh.py     3D neural mesh models (one per sub-type) and the clutter (background) model
- render.py          the differentiable vertex-feature splatter: pose -> projected vertices -> rendering likelihood
- pose.py            render-and-compare pose optimisation (the refinement step)
- color.py           the colour classifier on the object's crop (trained with the neural meshes)
- dynamics.py        velocity / acceleration / engine / floating from the estimated trajectory
- model.py           the render-and-compare parts together, saved to and loaded from weights/parser/
- train.py           `dynclevr train parser`
- evaluate.py        `dynclevr eval-parser`: the estimate against the truth
"""
