import itertools

import cv2
import numpy as np
import pytest
import typer
from typer.testing import CliRunner

from dynclevr.assets.catalogue import CATEGORIES, DENSITY, PARTS, SUBTYPES, get_asset
from dynclevr.assets.meshes import model_extents
from dynclevr.assets.sheet import draw_sheet, silhouette

NAMES = list(SUBTYPES)


def _components(mesh):
    return mesh.split(only_watertight=False)


def _ground_contacts(name: str) -> int:
    """Runs of filled pixels in the bottom row of the side silhouette: the wheels (or gear) touching the ground."""
    sil = silhouette(get_asset(name).mesh, "side", 192)
    rows = np.flatnonzero(sil.any(1))
    bottom = sil[rows[-1]].astype(int)
    return int(np.sum(np.diff(np.r_[0, bottom]) == 1))


@pytest.mark.parametrize("name", NAMES)
def test_every_subtype_builds_with_all_parts(name):
    a = get_asset(name)
    assert a.category == SUBTYPES[name][0] and a.category in CATEGORIES
    assert set(a.parts) == set(PARTS)
    for part, mesh in a.parts.items():
        assert len(mesh.faces) > 0, part
        assert np.isfinite(mesh.vertices).all()
    assert len(a.mesh.faces) < 6000


@pytest.mark.parametrize("name", NAMES)
def test_bbox_centred_with_catalogue_size(name):
    a = get_asset(name)
    lo, hi = a.mesh.bounds
    size = np.array(a.size)
    np.testing.assert_allclose((lo + hi) / 2, 0, atol=0.01 * size.max())
    np.testing.assert_allclose(hi - lo, size, rtol=0.02)
    assert 1.5 <= size[0] <= 4.6


@pytest.mark.parametrize("name", NAMES)
def test_models_are_built_near_their_size(name):
    # build_parts scales each axis to the catalogue size; near 1 so that wheels stay round
    scale = np.array(SUBTYPES[name][1]) / model_extents(name, SUBTYPES[name][1])
    assert np.all(np.abs(scale - 1) < 0.08), scale


@pytest.mark.parametrize("name", NAMES)
def test_mass_is_density_times_hull_volume(name):
    a = get_asset(name)
    assert a.volume > 0
    assert a.volume <= np.prod(a.size) * 1.001
    assert a.mass() == pytest.approx(DENSITY * a.volume)
    assert a.mass(1.0) == pytest.approx(a.volume)
    hull = a.collision_hull
    assert hull.ndim == 2 and hull.shape[1] == 3 and len(hull) >= 4
    assert (np.abs(hull) <= np.array(a.size) / 2 + 1e-6).all()
    assert get_asset(name).hull is a.hull               # cached, not rebuilt


def test_side_silhouettes_distinct():
    sils = {n: silhouette(get_asset(n).mesh, "side") for n in NAMES}
    for a, b in itertools.combinations(NAMES, 2):
        iou = (sils[a] & sils[b]).sum() / (sils[a] | sils[b]).sum()
        assert iou < 0.9, (a, b, iou)


def test_top_and_front_views_separate_same_sized_vehicles():
    # mountain and tandem bikes have the same front view; top views tell them apart (and vice versa for others)
    for cat in ("aeroplane", "bicycle", "motorbike"):
        names = [n for n in NAMES if SUBTYPES[n][0] == cat]
        sils = {n: np.concatenate([silhouette(get_asset(n).mesh, v).ravel() for v in ("top", "front")])
                for n in names}
        for a, b in itertools.combinations(names, 2):
            assert (sils[a] & sils[b]).sum() / (sils[a] | sils[b]).sum() < 0.8, (a, b)


def test_tandem_has_two_saddles():
    def saddles(name):
        a = get_asset(name)
        top = a.size[2] / 2
        return sum(1 for c in _components(a.parts["windows"])
                   if c.extents[0] > 0.2 and abs(c.centroid[1]) < 0.05 and c.centroid[2] > top * 0.4)

    assert saddles("tandem_bike") == 2
    for name in ("mountain_bike", "utility_bike", "road_bike"):
        assert saddles(name) == 1, name


def test_articulated_bus_has_three_axles_and_the_others_two():
    assert _ground_contacts("articulated_bus") == 3
    for name in ("double_bus", "school_bus", "regular_bus", "sedan", "truck", "mountain_bike", "tandem_bike",
                 "scooter", "chopper"):
        assert _ground_contacts(name) == 2, name


def test_double_bus_has_two_decks_of_windows():
    def window_bands(name):
        # side windows only (thin in y, on the left side), grouped by height
        zs = sorted(round(c.centroid[2], 1) for c in _components(get_asset(name).parts["windows"])
                    if c.extents[1] < 0.05 and c.centroid[1] > 0.5 and c.extents[2] > 0.3)
        return len(set(zs))

    assert window_bands("double_bus") == 2
    assert window_bands("regular_bus") == 1
    assert SUBTYPES["double_bus"][1][2] > SUBTYPES["regular_bus"][1][2] + 0.4


def test_school_bus_has_a_bonnet():
    def front_top_filled(name):
        sil = silhouette(get_asset(name).mesh, "side", 192)
        cols = np.flatnonzero(sil.any(0))
        rows = np.flatnonzero(sil.any(1))
        front = sil[rows[0]:rows[0] + (rows[-1] - rows[0]) // 3, cols[-1] - 8:cols[-1] + 1]
        return front.mean()

    assert front_top_filled("school_bus") < 0.05
    assert front_top_filled("regular_bus") > 0.8


def test_biplane_has_two_stacked_wings():
    def wing_layers(name):
        # rows of the front view where the outer fifth of each half-span is filled: one run per wing layer
        sil = silhouette(get_asset(name).mesh, "front", 192)
        cols = np.flatnonzero(sil.any(0))
        outer = sil[:, cols[0]:cols[0] + len(cols) // 10].any(1) & sil[:, cols[-1] - len(cols) // 10:].any(1)
        return int(np.sum(np.diff(np.r_[0, outer.astype(int)]) == 1))

    assert wing_layers("biplane") == 2
    for name in ("airliner", "fighter", "jet"):
        assert wing_layers(name) == 1, name


@pytest.mark.parametrize("name", [n for n in NAMES if SUBTYPES[n][0] == "car"])
def test_cars_have_tail_lights_at_the_rear(name):
    a = get_asset(name)
    lights = a.parts["lights"]
    assert lights.bounds[1][0] < -0.4 * a.size[0]
    assert len(_components(lights)) >= 2                # left and right


def test_scooter_has_small_wheels_and_dirtbike_tall_ones():
    def wheel_height(name):
        return max(c.extents[2] for c in _components(get_asset(name).parts["wheels"]))

    assert wheel_height("scooter") < 0.45 < 0.65 < wheel_height("dirtbike")


def test_sheet_is_written(tmp_path):
    path = tmp_path / "sheet.png"
    draw_sheet(path, 96)
    img = cv2.imread(str(path))
    assert img is not None and img.shape[0] > 5 * 96 and img.shape[1] >= 5 * 96
    assert (img < 200).any(-1).mean() > 0.08          # drawn vehicles, not a blank page


def test_assets_command_prints_the_table(tmp_path):
    from dynclevr.commands import assets

    app = typer.Typer()
    assets.register(app)
    result = CliRunner().invoke(app, ["--sheet", str(tmp_path / "s.png"), "--cell", "96"])
    assert result.exit_code == 0, result.output
    for name in NAMES:
        assert name in result.output
    assert (tmp_path / "s.png").stat().st_size > 10_000


def test_mesh_vertices_lie_on_a_micrometre_grid_so_every_cpu_builds_the_same_bytes():
    """numpy's SIMD math can differ in the last bit between CPUs; the collision shapes are checked against the mesh's
    bytes, so the builder rounds (and a -0.0 would still differ from 0.0)."""
    for name in SUBTYPES:
        for part in get_asset(name).parts.values():
            v = np.asarray(part.vertices)
            np.testing.assert_array_equal(v, np.round(v, 6), err_msg=name)
            assert not np.signbit(v[v == 0]).any(), name
