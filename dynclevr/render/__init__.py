"""Rendering: vehicle appearance (appearance.py), procedural environments (environments.py) and two backends with
one artifact schema (dynclevr/video.py): the fast TinyRenderer compositor (tiny.py) and the realistic Mitsuba 3
path tracer (mitsuba.py)."""

from __future__ import annotations

from dynclevr import DynclevrError

BACKENDS = ("tiny", "mitsuba")


class RenderError(DynclevrError):
    pass


def make_renderer(backend: str, scene, camera, env, variants: list[int], params: dict):
    """A context manager with `.render(t) -> (rgb, object ids, depth)` for one scene."""
    if backend == "tiny":
        from dynclevr.render.tiny import TinyRenderer

        return TinyRenderer(scene, camera, env, variants, supersample=params["supersample"],
                            shadows=params["shadows"])
    if backend == "mitsuba":
        from dynclevr.render.mitsuba import MitsubaRenderer, require_mitsuba

        require_mitsuba()
        return MitsubaRenderer(scene, camera, env, variants, spp=params["mitsuba_spp"], denoise=params["denoise"])
    raise RenderError(f"'render.backend' = {backend!r}: use one of {', '.join(BACKENDS)}")
