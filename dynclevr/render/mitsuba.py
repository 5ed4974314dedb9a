"""The realistic backend: Mitsuba 3 path tracing (LLVM variant, CPU) of the same scene, same environment.

What Mitsuba adds over the fast backend: global illumination from the environment (the procedural sky baked into
an equirectangular emitter), a sun with true shadows (vehicles on the ground and on each other), glossy and metallic
paint, reflective windows. What it shares, so the artifact is the same: the instance masks and depth come from the
TinyRenderer pass over the same geometry, and the ground's texture and the visible sky come from the same
Background as the fast backend's. The ground is path traced as a grey plane, denoised, and then multiplied by the
screen-space ground albedo (mip-filtered, lane marks included): so its texture never needs a Mitsuba texture nor
gets noise from the sampler. OptiX's denoiser is CUDA-only, and OpenCV's non-local means costs ~0.1 s a frame, so
frames are denoised by smoothing within each instance region (the masks are exact): edges stay sharp.

Installed by `make realistic` (pip install mitsuba; Debian's libLLVM 19, found through DRJIT_LIBLLVM_PATH).
"""

from __future__ import annotations

import glob
import os

import cv2
import numpy as np

from dynclevr.assets import get_asset
from dynclevr.camera import Camera
from dynclevr.render import RenderError
from dynclevr.render.appearance import part_material
from dynclevr.render.environments import Environment
from dynclevr.render.tiny import TinyRenderer, flat_geometry
from dynclevr.scene import Scene4D

VARIANT = "llvm_ad_rgb"
GROUND_GREY = 0.5          # linear albedo of the path-traced ground, divided out again when compositing
GROUND_RADIUS = 2000.0     # metres: past it nothing is seen but haze
LLVM_CANDIDATES = ("/usr/lib/x86_64-linux-gnu/libLLVM-19.so*", "/usr/lib/llvm-19/lib/libLLVM*.so*",
                   "/usr/lib/*/libLLVM-1[5-9].so*", "/usr/lib/*/libLLVM.so*")
INSTALL_HINT = "install it with `make realistic`, or set render.backend = \"tiny\""


def _find_llvm() -> None:
    if os.environ.get("DRJIT_LIBLLVM_PATH"):
        return
    for pattern in LLVM_CANDIDATES:
        found = sorted(glob.glob(pattern))
        if found:
            os.environ["DRJIT_LIBLLVM_PATH"] = found[0]
            return


def _import():
    _find_llvm()
    try:
        import drjit as dr
        import mitsuba as mi
    except ImportError:
        raise RenderError(f"the realistic backend needs Mitsuba 3, which is not installed: {INSTALL_HINT}") from None
    try:
        mi.set_variant(VARIANT)
    except (ImportError, AttributeError, RuntimeError) as e:
        raise RenderError(f"Mitsuba's {VARIANT} variant does not start ({e}); it needs libLLVM (Debian: libllvm19) "
                          f"found through DRJIT_LIBLLVM_PATH: {INSTALL_HINT}") from None
    return mi, dr


def require_mitsuba() -> None:
    _import()


def mitsuba_available() -> bool:
    try:
        _import()
        return True
    except RenderError:
        return False


def srgb_to_linear(x: np.ndarray) -> np.ndarray:
    x = np.clip(x, 0, None)
    return np.where(x <= 0.04045, x / 12.92, ((x + 0.055) / 1.055) ** 2.4).astype(np.float32)


def linear_to_srgb(x: np.ndarray) -> np.ndarray:
    x = np.clip(x, 0, None)
    return np.where(x <= 0.0031308, x * 12.92, 1.055 * x ** (1 / 2.4) - 0.055).astype(np.float32)


def _envmap_to_world():
    """Rotate Mitsuba's envmap frame (y up, u = atan2(x, -z)) to our world (z up) for a horizontally flipped
    equirectangular image (environments' layout): local = (world y, world z, world x)."""
    return [[0, 0, 1, 0], [1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 0, 1]]


def _denoise(lin: np.ndarray, labels: np.ndarray) -> np.ndarray:
    """Smooth path-tracing noise without crossing silhouettes (the masks are exact). The ground, grey irradiance
    here (its texture is multiplied in afterwards), takes a Gaussian normalised to its own region. Vehicles take,
    in display space, a 3x3 median (glossy paint sampled at 16 spp sparkles) and then an edge-preserving bilateral
    filter, so windows, wheels and lights stay sharp."""
    ground = (labels == -1).astype(np.float32)
    num = cv2.GaussianBlur(lin * ground[..., None], (0, 0), 2.0)
    den = cv2.GaussianBlur(ground, (0, 0), 2.0)[..., None]
    out = np.where(ground[..., None] > 0, num / np.maximum(den, 1e-6), lin)
    vehicles = labels >= 0
    if vehicles.any():
        srgb = cv2.medianBlur(np.clip(linear_to_srgb(lin) * 255 + 0.5, 0, 255).astype(np.uint8), 3)
        smooth = cv2.bilateralFilter(srgb.astype(np.float32) / 255, 7, 0.12, 3.0)
        out[vehicles] = srgb_to_linear(smooth[vehicles])
    return out


class MitsubaRenderer:
    def __init__(self, scene: Scene4D, camera: Camera, env: Environment, variants: list[int], spp: int = 16,
                 denoise: bool = True):
        mi, dr = _import()
        if os.environ.get("OMP_NUM_THREADS") == "1":   # a pool worker: the pool is the parallelism
            dr.set_thread_count(1)
        self.mi, self.scene, self.camera, self.env, self.spp, self.denoise = mi, scene, camera, env, spp, denoise
        # Masks, depth and the screen-space background come from the fast backend's exact geometry.
        self.tiny = TinyRenderer(scene, camera, env, variants, supersample=1, shadows=False)
        self.bg = self.tiny.bg
        self.meshes: list[list[tuple[object, np.ndarray]]] = []
        objects = {}
        for i, o in enumerate(scene.objects):
            parts = []
            for part, mesh in get_asset(o.shape).parts.items():
                material = part_material(part, o.color, variants[i])
                tri, _, uvs = flat_geometry(mesh, material.texture_scale)
                name = f"o{o.id}_{part}"
                objects[name] = self._mesh(name, tri, uvs, material)
                parts.append((name, tri))
            self.meshes.append(parts)
        sky = env.equirect(256)[:, ::-1]
        sky_lin = srgb_to_linear(sky)
        # The environment's sun and ambient are taken as linear irradiance (times pi) so that the path-traced ground
        # comes out as bright as the fast backend's; the sky is scaled so that its light on the ground is `ambient`.
        rows = np.radians(90 - 180 * (np.arange(sky.shape[0]) + 0.5) / sky.shape[0])
        w = np.clip(np.sin(rows), 0, None) * np.cos(rows)
        irradiance = (sky_lin.mean(1) * w[:, None]).sum(0) / w.sum()
        scale = float(np.mean(env.ambient) / max(irradiance.mean(), 1e-6))
        sun_lin = np.asarray(env.sun, np.float32)
        fov = float(np.degrees(2 * np.arctan(camera.width / 2 / camera.fx)))
        self.mscene = mi.load_dict({
            "type": "scene",
            # Direct light only (sky and sun, both shadowed, glossy reflections of the sky): at equal time it is
            # less noisy than a path tracer with one more bounce, whose only gain is faint colour bleeding.
            "integrator": {"type": "direct"},
            "sensor": {"type": "perspective", "fov": fov, "fov_axis": "x",
                       "to_world": mi.ScalarTransform4f().look_at(origin=list(camera.position),
                                                                 target=list(camera.look_at), up=[0, 0, 1]),
                       "sampler": {"type": "independent", "sample_count": spp},
                       "film": {"type": "hdrfilm", "width": camera.width, "height": camera.height,
                                "rfilter": {"type": "box"}, "pixel_format": "rgb"}},
            "sky": {"type": "envmap", "bitmap": mi.Bitmap(np.ascontiguousarray(sky_lin)), "scale": scale,
                    "to_world": mi.ScalarTransform4f(_envmap_to_world())},
            "sun": {"type": "directional", "direction": (-env.sun_dir).tolist(),
                    "irradiance": {"type": "rgb", "value": (np.pi * sun_lin).tolist()}},
            "ground": {"type": "disk", "to_world": mi.ScalarTransform4f().scale([GROUND_RADIUS] * 3),
                       "bsdf": {"type": "diffuse", "reflectance": {"type": "rgb", "value": [GROUND_GREY] * 3}}},
            **objects,
        }, optimize=False)
        self.params = mi.traverse(self.mscene)
        self.seed = 0

    def _mesh(self, name: str, tri: np.ndarray, uvs: np.ndarray, material):
        mi = self.mi
        if material.uniform:
            base = {"type": "rgb", "value": srgb_to_linear(material.mean_rgb / 255).tolist()}
        else:
            base = {"type": "bitmap", "bitmap": mi.Bitmap(np.ascontiguousarray(material.texture)),
                    "filter_type": "bilinear"}
        props = mi.Properties()
        props["bsdf"] = mi.load_dict({"type": "principled", "base_color": base, "roughness": material.roughness,
                                      "metallic": material.metallic, "specular": 0.35})
        mesh = mi.Mesh(name, len(tri), len(tri) // 3, has_vertex_normals=False, has_vertex_texcoords=True,
                       props=props)
        p = mi.traverse(mesh)
        p["vertex_positions"] = mi.Float(tri.astype(np.float32).ravel())
        p["faces"] = mi.UInt32(np.arange(len(tri), dtype=np.uint32))
        p["vertex_texcoords"] = mi.Float(uvs.astype(np.float32).ravel())
        p.update()
        return mesh

    def _pose(self, t: int) -> None:
        from scipy.spatial.transform import Rotation

        for i, parts in enumerate(self.meshes):
            R = Rotation.from_quat(self.scene.orientation[t, i]).as_matrix()
            pos = self.scene.position[t, i]
            for name, tri in parts:
                self.params[f"{name}.vertex_positions"] = self.mi.Float((tri @ R.T + pos).astype(np.float32).ravel())
        self.params.update()

    def render(self, t: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        mask, depth = self.tiny.labels(t)
        self._pose(t)
        # The sampler's seed is the frame index: deterministic frames, and noise that does not freeze in place.
        lin = np.asarray(self.mi.render(self.mscene, spp=self.spp, seed=t), np.float32)
        ground = (mask < 0) & np.isfinite(depth)
        if self.denoise:
            lin = _denoise(lin, np.where(ground, -1, np.where(mask < 0, -2, mask)))
        bg = self.bg
        ground_rgb = linear_to_srgb(srgb_to_linear(bg.albedo) * lin / GROUND_GREY) * bg.clear[..., None] + (
            bg.rgb - (bg.ambient + bg.sun))
        out = np.where(ground[..., None], ground_rgb, linear_to_srgb(lin))
        out = np.where(((mask < 0) & ~ground)[..., None], bg.rgb, out)
        return np.clip(out * 255 + 0.5, 0, 255).astype(np.uint8), mask, depth

    def close(self) -> None:
        self.tiny.close()

    def __enter__(self) -> "MitsubaRenderer":
        return self

    def __exit__(self, *exc):
        self.close()
        return False
