"""The fast backend: vehicles rasterised by pybullet's TinyRenderer, composited over an analytic sky and ground.

Why split the work: the camera never moves within a video, so the sky and the textured ground (an infinite plane,
mip-mapped so that distant ground blurs rather than aliases, hazed towards the horizon) are computed once per
scene with numpy. TinyRenderer then draws only the vehicles each frame, which also gives exact instance masks
(its segmentation buffer) and depth (its z-buffer). Shadows are the vehicles' silhouettes projected along the sun
onto the ground, plus a soft contact shadow under each vehicle, so vehicles stand on the ground instead of floating.
The background is computed at twice the resolution and area-averaged once. Vehicles are drawn at `supersample` x the
resolution and area-averaged (then masks take each pixel's majority label and depth the mean of its samples with that
label); at supersample 1 (the default: 4x cheaper) their silhouette pixels are softened by a 3x3 average instead.
"""

from __future__ import annotations

import os
import shutil
import tempfile

import cv2
import numpy as np

from dynclevr.assets import get_asset
from dynclevr.camera import Camera
from dynclevr.render.appearance import part_material
from dynclevr.render.environments import Environment
from dynclevr.scene import Scene4D

NEAR, FAR = 0.05, 400.0
MAX_GROUND_M = 5000.0   # rays closer than this to the horizon count as sky-coloured haze


def gl_projection(camera: Camera) -> list[float]:
    """OpenGL projection matching the pinhole K exactly (principal point at the image centre), column-major.

    TinyRenderer samples pixel (i, j) at the point (i, j) of its viewport, where K's pixel centres lie at (i + 0.5,
    j + 0.5): without the half-pixel terms below, vehicles and masks land 0.5 px right of and above where the
    recorded calibration projects them (tests/test_render.py measures it)."""
    W, H, f = camera.width, camera.height, camera.fx
    P = np.array([[2 * f / W, 0, 1 / W, 0], [0, 2 * f / H, 1 / H, 0],
                  [0, 0, -(FAR + NEAR) / (FAR - NEAR), -2 * FAR * NEAR / (FAR - NEAR)], [0, 0, -1, 0]])
    return P.ravel(order="F").tolist()


def gl_view(camera: Camera) -> list[float]:
    """OpenGL view matrix (x right, y up, z backwards) from our OpenCV extrinsics, column-major."""
    V = np.diag([1.0, -1.0, -1.0, 1.0]) @ camera.world_to_camera
    return V.ravel(order="F").tolist()


def camera_rays(camera: Camera) -> np.ndarray:
    """World directions [H, W, 3] through pixel centres, scaled so the camera-frame z component is 1."""
    u, v = np.meshgrid(np.arange(camera.width) + 0.5, np.arange(camera.height) + 0.5)
    d_cam = np.stack([(u - camera.width / 2) / camera.fx, (v - camera.height / 2) / camera.fx, np.ones_like(u)], -1)
    return d_cam @ camera.world_to_camera[:3, :3]


def ground_depth(camera: Camera, rays: np.ndarray | None = None) -> np.ndarray:
    """Depth along the optical axis of the ground plane per pixel (inf where the ray sees sky)."""
    rays = camera_rays(camera) if rays is None else rays
    ground = rays[..., 2] < -1e-9
    t = np.where(ground, -float(camera.position[2]) / np.where(ground, rays[..., 2], -1.0), np.inf)
    return np.where(t * np.linalg.norm(rays, axis=-1) < MAX_GROUND_M, t, np.inf).astype(np.float32)


def flat_geometry(mesh, texture_scale: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """A mesh as separate triangles (vertices [3F, 3], face normals per vertex, texture coordinates [3F, 2]):
    flat shading, and box-projected texture coordinates (each face takes the plane its normal is most
    perpendicular to, `texture_scale` metres per texture tile)."""
    tri = np.asarray(mesh.vertices)[np.asarray(mesh.faces)].reshape(-1, 3)
    normals = np.repeat(np.asarray(mesh.face_normals), 3, axis=0)
    axis = np.argmax(np.abs(normals), axis=1)
    other = np.array([[1, 2], [0, 2], [0, 1]])[axis]
    return tri, normals, np.take_along_axis(tri, other, 1) / texture_scale


class Background:
    """Sky and ground as one camera sees them, split into the ambient and the sun's share so shadows can remove
    the sun. Computed at `oversample` x the camera's resolution and area-averaged."""

    def __init__(self, camera: Camera, env: Environment, oversample: int = 2):
        lo = camera
        camera = camera.with_resolution(camera.width * oversample, camera.height * oversample)
        eye = np.asarray(camera.position, float)
        rays = camera_rays(camera)
        t = ground_depth(camera, rays)
        ground = np.isfinite(t)
        tt = np.where(ground, t, 0.0)
        hit = eye + rays * tt[..., None]
        dist = tt * np.linalg.norm(rays, axis=-1)
        # Footprint of a pixel on the ground: how far the hit point moves to the next pixel.
        fx = np.linalg.norm(np.gradient(hit, axis=1), axis=-1)
        fy = np.linalg.norm(np.gradient(hit, axis=0), axis=-1)
        footprint = np.where(ground, np.maximum(fx, fy), 1e3)
        albedo = np.zeros(rays.shape, np.float32)
        albedo[ground] = env.ground_albedo(hit[ground][:, 0], hit[ground][:, 1], footprint[ground])
        clear = np.exp(-dist / env.haze_m)[..., None].astype(np.float32)
        sun_z = max(float(env.sun_dir[2]), 0.0)
        self.ambient = (albedo * env.ambient * clear).astype(np.float32)
        self.sun = (albedo * env.sun * sun_z * clear).astype(np.float32)
        haze = (1 - clear) * env.haze
        self.rgb = (self.ambient + self.sun + haze).astype(np.float32)
        self.rgb[~ground] = env.sky_radiance(rays[~ground])
        self.albedo, self.clear = albedo, np.where(ground, clear[..., 0], 0).astype(np.float32)   # clear: 2-D
        if oversample > 1:
            size = (lo.width, lo.height)
            self.rgb, self.ambient, self.sun, self.albedo, self.clear = (
                cv2.resize(a, size, interpolation=cv2.INTER_AREA)
                for a in (self.rgb, self.ambient, self.sun, self.albedo, self.clear))


class TinyRenderer:
    """Render one scene: `r = TinyRenderer(scene, camera, env, variants)`, then `r.render(t)` per frame."""

    def __init__(self, scene: Scene4D, camera: Camera, env: Environment, variants: list[int], supersample: int = 1,
                 shadows: bool = True):
        from dynclevr.physics import p   # pybullet, imported with its banner silenced

        self.p, self.scene, self.camera, self.env, self.ss, self.shadows = p, scene, camera, env, supersample, shadows
        self.hi = camera.with_resolution(camera.width * supersample, camera.height * supersample)
        self.client = p.connect(p.DIRECT)
        self._tmp = tempfile.mkdtemp(prefix="dynclevr-tiny-")
        self.view, self.proj = gl_view(self.hi), gl_projection(self.hi)
        self._P = self.hi.K @ self.hi.world_to_camera[:3]   # 3x4 pinhole projection of world points
        self.bg = Background(self.hi, env, oversample=max(1, 2 // supersample))
        self._bg_depth = ground_depth(camera)
        self._back8 = np.clip(self.bg.rgb * 255 + 0.5, 0, 255).astype(np.uint8)
        self.bodies: list[list[int]] = []     # per object: its part bodies
        self.hulls: list[list[np.ndarray]] = []   # per object: convex hull vertices per part (object frame)
        lut = {}
        for i, o in enumerate(scene.objects):
            asset = get_asset(o.shape)
            uids, hulls = [], []
            for part, mesh in asset.parts.items():
                uid = self._add_part(mesh, part_material(part, o.color, variants[i]))
                lut[uid] = o.id
                uids.append(uid)
                hulls.append(np.asarray(mesh.convex_hull.vertices))
            self.bodies.append(uids)
            self.hulls.append(hulls)
        self.lut = np.full(max(lut, default=0) + 2, -1, np.int16)
        for uid, oid in lut.items():
            self.lut[uid] = oid
        sun = np.asarray(env.sun, float)
        self.light = dict(lightDirection=env.sun_dir.tolist(), lightColor=(sun / sun.max()).tolist(),
                          lightDiffuseCoeff=float(sun.max()), lightAmbientCoeff=float(np.mean(env.ambient)),
                          lightSpecularCoeff=0.35, shadow=0)

    def _add_part(self, mesh, material) -> int:
        p = self.p
        tri, normals, uvs = flat_geometry(mesh, material.texture_scale)
        spec = [1.0 - material.roughness] * 3
        kw = dict(vertices=tri.tolist(), indices=list(range(len(tri))), normals=normals.tolist(), uvs=uvs.tolist(),
                  specularColor=spec, physicsClientId=self.client)
        # A patterned material is a texture with a white tint; a plain one needs no texture.
        colour = [*(material.mean_rgb / 255), 1.0] if material.uniform else [1.0, 1.0, 1.0, 1.0]
        vs = p.createVisualShape(p.GEOM_MESH, rgbaColor=colour, **kw)
        uid = p.createMultiBody(0, -1, vs, physicsClientId=self.client)
        if not material.uniform:
            path = os.path.join(self._tmp, f"{uid}.png")
            cv2.imwrite(path, cv2.cvtColor(material.texture, cv2.COLOR_RGB2BGR))
            tex = p.loadTexture(path, physicsClientId=self.client)
            p.changeVisualShape(uid, -1, textureUniqueId=tex, rgbaColor=[1, 1, 1, 1], physicsClientId=self.client)
        return uid

    def close(self) -> None:
        self.p.disconnect(self.client)
        shutil.rmtree(self._tmp, ignore_errors=True)

    def __enter__(self) -> "TinyRenderer":
        return self

    def __exit__(self, *exc):
        self.close()
        return False

    # ---- one frame ---------------------------------------------------------------------------------------------

    def _pose(self, t: int) -> None:
        for i, uids in enumerate(self.bodies):
            pos, quat = self.scene.position[t, i].tolist(), self.scene.orientation[t, i].tolist()
            for uid in uids:
                self.p.resetBasePositionAndOrientation(uid, pos, quat, physicsClientId=self.client)

    def _shadow(self, t: int) -> tuple[np.ndarray, np.ndarray]:
        """(sun shadow, contact shadow) coverage in [0, 1] on the supersampled image."""
        from scipy.spatial.transform import Rotation

        H, W = self.hi.height, self.hi.width
        sun_mask = np.zeros((H, W), np.uint8)
        contact = np.zeros((H, W), np.uint8)
        L = self.env.sun_dir
        scale = 16  # cv2 draws with 4 fractional bits
        for i, hulls in enumerate(self.hulls):
            R = Rotation.from_quat(self.scene.orientation[t, i]).as_matrix()
            pos = self.scene.position[t, i]
            for h in hulls:
                w = h @ R.T + pos
                if L[2] > 0.05:
                    g = w - (np.maximum(w[:, 2:3], 0) / L[2]) * L
                    self._fill(sun_mask, g, scale)
            lo = min(float((h @ R.T + pos)[:, 2].min()) for h in hulls)
            strength = int(255 * np.clip(1 - lo / 0.8, 0, 1))
            if strength > 0:
                size = np.asarray(self.scene.objects[i].size) * [0.55, 0.6, 0]
                corners = np.array([[sx, sy, 0] for sx in (-1, 1) for sy in (-1, 1)]) * size
                foot = corners @ R.T + pos * [1, 1, 0]
                self._fill(contact, foot, scale, strength)
        blur = max(3, 2 * (self.ss * 2) + 1)
        sun_f = cv2.GaussianBlur(sun_mask, (blur, blur), 0).astype(np.float32) / 255
        k = 6 * self.ss * 2 + 1
        contact_f = cv2.GaussianBlur(contact, (k, k), 0).astype(np.float32) / 255
        return sun_f, contact_f

    def _fill(self, img: np.ndarray, ground_pts: np.ndarray, scale: int, value: int = 255) -> None:
        q = ground_pts @ self._P[:, :3].T + self._P[:, 3]
        if (q[:, 2] <= NEAR).any():
            return
        # cv2 puts pixel centres at integers, K at half-integers
        hull = cv2.convexHull(np.round((q[:, :2] / q[:, 2:] - 0.5) * scale).astype(np.int32))
        cv2.fillConvexPoly(img, hull, value, lineType=cv2.LINE_AA, shift=4)

    def _raster(self, t: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """TinyRenderer's view of the vehicles at frame t: (rgba, object ids, depth), supersampled."""
        p, hi = self.p, self.hi
        self._pose(t)
        _, _, rgba, zbuf, seg = p.getCameraImage(hi.width, hi.height, self.view, self.proj,
                                                 renderer=p.ER_TINY_RENDERER, physicsClientId=self.client,
                                                 **self.light)
        rgba = np.asarray(rgba, np.uint8).reshape(hi.height, hi.width, 4)
        seg = np.asarray(seg).reshape(hi.height, hi.width)
        ids = np.where(seg >= 0, self.lut[np.clip(seg, 0, len(self.lut) - 1)], -1).astype(np.int16)
        zbuf = np.asarray(zbuf, np.float32).reshape(hi.height, hi.width)
        return rgba, ids, FAR * NEAR / (FAR - (FAR - NEAR) * zbuf)

    def labels(self, t: int) -> tuple[np.ndarray, np.ndarray]:
        """Frame t's (object ids, depth) alone: what another backend reuses so every backend has the same truth."""
        _, ids, z = self._raster(t)
        return _downsample_labels(ids, z, self.ss, self._bg_depth)

    def render(self, t: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Frame t -> (rgb uint8 [H, W, 3], object ids int16 [H, W] with -1 elsewhere, depth float32 [H, W] m)."""
        rgba, ids, z = self._raster(t)

        bg = self.bg
        back8 = self._back8.copy()
        if self.shadows:
            sun_f, contact_f = self._shadow(t)
            dark = (sun_f > 0) | (contact_f > 0)   # shadows cover a small part of the frame: shade only there
            back8[dark] = np.clip((bg.rgb[dark] - bg.sun[dark] * sun_f[dark][:, None]
                                   - bg.ambient[dark] * (0.55 * contact_f[dark][:, None])) * 255 + 0.5, 0, 255)
        hi_rgb = np.where((ids >= 0)[..., None], rgba[..., :3], back8)
        W, H, s = self.camera.width, self.camera.height, self.ss
        if s > 1:
            rgb = cv2.resize(hi_rgb, (W, H), interpolation=cv2.INTER_AREA)
        else:
            edge = np.zeros(ids.shape, bool)
            edge[:, 1:] |= ids[:, 1:] != ids[:, :-1]
            edge[1:] |= ids[1:] != ids[:-1]
            edge[:, :-1] |= edge[:, 1:].copy()
            edge[:-1] |= edge[1:].copy()
            rgb = hi_rgb.copy()
            rgb[edge] = cv2.blur(hi_rgb, (3, 3))[edge]
        mask, depth = _downsample_labels(ids, z, s, self._bg_depth)
        return rgb, mask, depth


def _downsample_labels(ids: np.ndarray, z: np.ndarray, s: int, background_depth: np.ndarray):
    """Majority label per s x s block (background counts as a label) and the mean depth of that label's samples."""
    if s == 1:
        return ids, np.where(ids >= 0, z, background_depth).astype(np.float32)
    H, W = ids.shape[0] // s, ids.shape[1] // s
    blocks = ids.reshape(H, s, W, s)
    zb = z.reshape(H, s, W, s)
    best = np.full((H, W), -1, np.int16)
    best_n = (blocks < 0).sum((1, 3))
    depth = background_depth.copy()
    for oid in np.unique(ids[ids >= 0]):
        sel = blocks == oid
        n = sel.sum((1, 3))
        win = n > best_n
        if win.any():
            best[win], best_n[win] = oid, n[win]
            depth[win] = ((zb * sel).sum((1, 3)) / np.maximum(n, 1))[win]
    return best, depth.astype(np.float32)
