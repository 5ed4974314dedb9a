import numpy as np
import pytest

from dynclevr.artifacts import ArtifactError
from dynclevr.mcapio import McapOut
from dynclevr.scene import SCENE_VERSION, Scene4D


def test_scene_roundtrip_and_bytes(tiny_scene, tmp_path):
    a, b = tmp_path / "a.mcap", tmp_path / "b.mcap"
    tiny_scene.write(a, kind="truth")
    tiny_scene.write(b, kind="truth")
    assert a.read_bytes() == b.read_bytes()  # no wall clock in files
    back = Scene4D.read(a)
    assert [o.shape for o in back.objects] == ["sedan", "school_bus"]
    np.testing.assert_allclose(back.position, tiny_scene.position)
    assert back.collisions[0].pair() == frozenset({0, 1})
    assert back.counterfactuals == {(1, "static"): []}
    assert back.camera == tiny_scene.camera
    assert back.cut_state is None and back.cut_collisions is None   # the truth is causal: no separate cut
    cut = {"position": np.ones((2, 3)), "orientation": np.tile([0.0, 0.0, 0.0, 1.0], (2, 1)),
           "velocity": np.full((2, 3), 2.5), "angular_velocity": np.zeros((2, 3)),
           "engine": np.array([True, False]), "floating": np.array([False, False])}
    tiny_scene.cut_state, tiny_scene.cut_collisions = cut, []
    tiny_scene.write(a, kind="estimate")
    back = Scene4D.read(a)
    for k, v in cut.items():
        np.testing.assert_array_equal(back.cut_state[k], v)
    assert back.cut_collisions == [] and back.collisions   # none known at the cut, some seen later


def test_corrupt_and_wrong_version(tiny_scene, tmp_path):
    p = tmp_path / "000000.mcap"
    tiny_scene.write(p, kind="truth")
    p.write_bytes(p.read_bytes()[: len(p.read_bytes()) // 2])
    with pytest.raises(ArtifactError, match="not a readable MCAP|corrupt"):
        Scene4D.read(p)
    with McapOut(p, "dynclevr.scene4d", 99):
        pass
    with pytest.raises(ArtifactError, match=f"v99, expected dynclevr.scene4d v{SCENE_VERSION}"):
        Scene4D.read(p)
