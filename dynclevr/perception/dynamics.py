"""Dynamics attributes from the estimated trajectory (REFERENCE.md section 2.3), causal: frame t uses frames <= t.

With the physics prior the velocity is the filter's (tracker.py) and the acceleration its `slope`; the engine is
and an aeroplane's floating decided from a `QuadraticFit` of the measurements. Without the prior (the paper's ablation), as follows.

The paper takes finite differences of the positions and smooths them with a moving average of 5 frames. With
centimetres of pose noise per frame that gives velocities good to about half a metre per second, and accelerations
(a second difference) with metres per second squared of noise: far above the ~2 m/s^2 that separate an engine from
friction alone, and the executor's "accelerating" reads the change of these velocities. So here velocity and
acceleration are the first and second derivatives, at the current frame, of a least-squares quadratic fit to the
track's last `fit_window` positions (the same smoothing of finite differences, with a longer window that a
quadratic makes lag-free under constant acceleration). A collision breaks the motion, so the fit restarts at the
object's last contact in the physics engine.

- engine: moving and accelerating forwards (along its heading) by more than `engine_threshold`;
- floating: an aeroplane off the ground that is not falling (vertical acceleration above -g/2);
- static: a fitted speed under `static_speed` is reported as exactly 0 (a zero-velocity detector: pose noise
  alone would otherwise make every parked vehicle creep at a few tenths of a metre per second);
- speed class: the initial speed's nearest class speed (0, physics.slow_speed, physics.fast_speed).
"""

from __future__ import annotations

import math

import numpy as np

from dynclevr.physics import heading


def motion(pos: np.ndarray, fps: int, min_frames: int, short_frames: int | None = None
           ) -> tuple[np.ndarray, np.ndarray]:
    """(velocity, acceleration) at the last of `pos` [n, 3] (the positions to fit, oldest first).

    `short_frames` (<= min_frames): from that many positions a linear fit already gives a velocity (a young track:
    without one the physics prior predicts it parked and pins it where it was found, and it reads as static).

    Fewer than `min_frames` positions give no velocity, fewer than twice that no acceleration: from two or three
    noisy poses a difference is mostly noise (5 cm of jitter between two frames reads as 3 m/s), and fed back into
    the physics prior as an engine or a speed it would push the estimate away from the object."""
    n = len(pos)
    if n < max(min(short_frames or min_frames, min_frames), 2):
        return np.zeros(3), np.zeros(3)
    quadratic = n >= 2 * min_frames
    coef = _fit((np.arange(n) - (n - 1)) / fps, pos, quadratic)
    return coef[1], (coef[2] if quadratic else np.zeros(3))


def _fit(t: np.ndarray, pos: np.ndarray, quadratic: bool) -> np.ndarray:
    """Least-squares (position, velocity[, acceleration]) at t = 0 of positions [n, 3] at times t [n] (s)."""
    A = np.stack([np.ones_like(t), t, 0.5 * t * t] if quadratic else [np.ones_like(t), t], 1)
    return np.linalg.lstsq(A, pos, rcond=None)[0]


class QuadraticFit:
    """A least-squares quadratic through (frame, position) samples: its acceleration, and its velocity at any
    frame. Fewer than `min_samples` samples: no fit (zero acceleration and velocity)."""

    def __init__(self, samples: list[tuple[int, np.ndarray]], fps: int, min_samples: int, robust: bool = False):
        """`robust`: without the samples it explains worst (`_robust_fit`)."""
        self.fps = fps
        self.ok = len(samples) >= min_samples
        self.centre, self.coef = 0.0, np.zeros((3, 3))
        if self.ok:
            t = np.array([f for f, _ in samples], float) / fps
            self.centre = float(t.mean())
            x = np.array([x for _, x in samples])
            coef = _robust_fit(t - self.centre, x, min_samples // 2) if robust else _fit(t - self.centre, x, True)
            self.coef[:len(coef)] = coef

    @property
    def acceleration(self) -> np.ndarray:
        return self.coef[2]

    def velocity(self, frame: int) -> np.ndarray:
        return self.coef[1] + self.coef[2] * (frame / self.fps - self.centre)


def slope(values: np.ndarray, fps: int) -> np.ndarray:
    """Least-squares slope per second of `values` [n, ...] sampled once a frame (n >= 2)."""
    t = (np.arange(len(values)) - (len(values) - 1) / 2) / fps
    return np.tensordot(t, values - values.mean(0), axes=1) / float(t @ t)


def spin(quats: np.ndarray, seen: np.ndarray, impacts: list[int], fps: int, window: int, significance: float,
         min_frames: int) -> np.ndarray:
    """The yaw rate (rad/s) per frame of the headings `quats` [n, 4], causal; `seen` [n] the frames with a detection,
    `impacts` the body's impacts (frames on the same axis).

    Nothing spins a body but an impact (the generator launches every one straight), so before its first impact the
    rate is 0. After one it is the slope of a line through the heading over the seen frames among the last `window`
    since that impact (at least `min_frames` of them), where that slope is `significance` standard errors from 0;
    else 0. Differences of the heading over a few frames read the head's heading noise as spin: on full-test they
    correlate 0.06 with the true spin at the cut, and a body without spin is then a better guess than them."""
    fwd = heading(quats)
    yaw = np.unwrap(np.arctan2(fwd[:, 1], fwd[:, 0]))
    impacts = set(impacts)
    out = np.zeros(len(yaw))
    last = -1
    for t in range(len(yaw)):
        last = t if t in impacts else last
        if last < 0:
            continue
        f = np.arange(max(last + 1, t - window + 1), t + 1)
        f = f[seen[f]]
        if len(f) < max(min_frames, 3):
            continue
        s = (f - f.mean()) / fps
        slope = s @ (yaw[f] - yaw[f].mean()) / (s @ s)
        residual = yaw[f] - yaw[f].mean() - slope * s
        if abs(slope) > significance * math.sqrt(residual @ residual / (len(f) - 2) / (s @ s)):
            out[t] = slope
    return out


def engine_on(vel: np.ndarray, acc: np.ndarray, quat: np.ndarray, p: dict) -> bool:
    fwd = heading(quat)
    return bool(np.linalg.norm(vel[:2]) > p["static_speed"] and float(acc @ fwd) > p["engine_threshold"])


def floating(category: str, z: float, half_height: float, acc: np.ndarray, gravity: float) -> bool:
    return category == "aeroplane" and z > half_height + 0.2 and float(acc[2]) > -gravity / 2


class VerticalMotion:
    """An aeroplane's height under the physics prior (REFERENCE.md section 1): every plane starts with no vertical
    velocity at frame 0, and either floats (its force cancels gravity: it holds its height) or falls from there
    under gravity to its resting height. Which one, and the start height z0, are fitted to measured heights.

    The head's heights drift smoothly by decimetres over a track (its distance error moves the placed centre along
    the camera ray), so a free quadratic read 5 of full-test's 51 floating planes as falling (airliners at -5.5 to
    -6.2 m/s^2); the two physical motions differ by half a metre within 20 frames of a fall."""

    def __init__(self, samples: list[tuple[int, np.ndarray]], fps: int, gravity: float, rest: float):
        """`samples`: (frame, measured position); `rest`: the sub-type's resting height."""
        t = np.array([f for f, _ in samples], float) / fps
        z = np.array([x[2] for _, x in samples], float)
        self.fps, self.gravity, self.rest = fps, gravity, rest
        grid = np.arange(rest, max(float(z.max()), rest) + 2.0, 0.01)[:, None]

        def best(model):
            cost = (np.minimum(np.abs(z - model(grid)), TRUNCATE) ** 2).sum(1)
            k = int(cost.argmin())
            return float(cost[k]), float(grid[k, 0])

        cost_float, z_float = best(lambda z0: np.broadcast_to(z0, (len(grid), len(t))))
        cost_fall, z_fall = best(lambda z0: np.maximum(z0 - 0.5 * gravity * t ** 2, rest))
        self.floating = cost_float <= cost_fall
        self.z0 = z_float if self.floating else z_fall

    def vz(self, frame: int) -> float:
        """Vertical velocity at `frame` before any impact: 0 floating; falling, -g t until it reaches the ground
        (then None: it bounces, which the model does not follow)."""
        if self.floating:
            return 0.0
        t = frame / self.fps
        return -self.gravity * t if self.z0 - 0.5 * self.gravity * t * t > self.rest else None


def floating_vz(heights: np.ndarray, fps: int, min_samples: int, held: bool = False) -> np.ndarray | None:
    """A floating body's vertical velocity [n] over a stretch from its measured heights [n] (NaN: no detection): its
    force cancels gravity, so nothing but an impact changes its vertical velocity, and its heights lie on lines
    (fitted robust to bad detections) that change slope at impacts. `held`: the stretch starts at the body's start,
    where it has none (REFERENCE.md section 1), so its first line is level. The parser misses some impacts (a plane
    grazed by another, a ground vehicle hitting its belly: the collision classifier reads horizontal motions), so a
    line splits in two where that lowers its cost by FLOAT_BREAK_COST and the slope changes by FLOAT_KICK or more:
    the head's heights drift by a decimetre or two over a whole track (its distance error moves the centre along the
    camera ray), an impact's kick is metres per second. None with fewer than min_samples measurements."""
    seen = np.isfinite(heights)
    if seen.sum() < min_samples:
        return None
    t = np.arange(len(heights)) / fps

    def line(a: int, b: int, level: bool) -> tuple[float, float] | None:
        """(cost, slope) of the line through the heights of frames a..b."""
        ok = seen[a:b]
        if ok.sum() < min_samples:
            return None
        tt, zz = t[a:b][ok], heights[a:b][ok]
        if level:
            coef = float(np.median(zz)), 0.0
        else:
            coef = _robust_fit(tt, zz[:, None], min_samples, quadratic=False)[:, 0]
        return float((np.minimum(np.abs(zz - coef[0] - coef[1] * tt), TRUNCATE) ** 2).sum()), float(coef[1])

    pieces = [(0, len(heights), held, line(0, len(heights), held))]
    done = []
    while pieces:   # split each piece at its best break while one pays (binary segmentation)
        a, b, level, (cost, slope) = pieces.pop()
        best = None
        for s in range(a + min_samples, b - min_samples + 1):
            left, right = line(a, s, level), line(s, b, False)
            if left and right and abs(right[1] - left[1]) >= FLOAT_KICK and (
                    best is None or left[0] + right[0] < best[0]):
                best = left[0] + right[0], s, left, right
        if best is not None and best[0] + FLOAT_BREAK_COST < cost:
            _, s, left, right = best
            pieces += [(a, s, level, left), (s, b, False, right)]
        else:
            done.append((a, b, slope))
    vz = np.zeros(len(heights))
    for a, b, slope in done:
        vz[a:b] = slope
    return vz


def front_back_heading(yaws: np.ndarray, support_cap: int, yaw_sigma: float, measure_yaw: float,
                       flip_weight: float = 1.0) -> np.ndarray:
    """The heading per frame from the head's readings `yaws` [n] (NaN: none), causal (frame t reads frames <= t).

    A body turns a few degrees a frame, even spun by an impact (the data's 90th percentile is 1.6 rad/s, under
    2 degrees a frame at 60 fps). So a reading within 45 degrees of the heading so far confirms it; one facing
    against it is the head's front/back flip, folded back; one further off either way is the head's confusion,
    skipped. Flips (each `flip_weight`) and confusions (each 1) count against the heading, confirmations for it
    (at most `support_cap`): where those against outnumber them, the heading was the flip (it turns round) or the
    body turned where the head lost it (the heading restarts at the reading). A filter that took each flip as a
    turn would be dragged by its gain times 180 degrees, to either side.

    Why a flip weighs less than a confusion: a body that truly turns round passes through the angles between, which
    the head reads as confusions, while a run of flips is the head reading a body backwards. That happens mostly
    after an impact, when the body's motion no longer tells its front: full-test's long runs of reported headings
    flipped against the truth had the head's readings flipped in nearly all their frames, and the confusions
    during the impact had spent the support that the frames before it had built."""
    out = np.full(len(yaws), np.nan)
    yaw, var, support = None, 0.0, 0.0
    for t, y in enumerate(yaws):
        var += yaw_sigma ** 2
        if not np.isnan(y):
            off = abs(wrap(y - yaw)) if yaw is not None else 0.0
            if off <= np.pi / 4:
                support = min(support + 1, support_cap)
            else:
                support -= flip_weight if off >= 0.75 * np.pi else 1.0
            if yaw is None or support < 0 and off < 0.75 * np.pi:
                yaw, var, support, off = float(y), measure_yaw ** 2, 1, 0.0
            elif support < 0:
                yaw, support, off = yaw + np.pi, 1, 0.0
            elif off >= 0.75 * np.pi:
                y, off = y + np.pi, 0.0
            if off <= np.pi / 4:
                gain = var / (var + measure_yaw ** 2)
                var *= 1 - gain
                yaw = wrap(yaw + gain * wrap(y - yaw))
        if yaw is not None:
            out[t] = yaw
    return out


def wrap(a: float) -> float:
    """An angle in (-pi, pi]."""
    return math.atan2(math.sin(a), math.cos(a))


def speed_class(speed: float, slow: float, fast: float) -> str:
    centres = {"static": 0.0, "slow": slow, "fast": fast}
    return min(centres, key=lambda k: abs(centres[k] - speed))


def smoothed_motion(z: np.ndarray, breaks: list[int], fps: int, half_window: int, min_samples: int
                    ) -> tuple[np.ndarray, np.ndarray]:
    """Non-causal (position, velocity) [n, 3] at each frame of a track from its measured positions z [n, 3] (NaN:
    no detection): the value and derivative at the frame of a least-squares fit to the measurements within
    +-half_window frames, not across a break (an impact, or a change of motion the engine missed; indices into z).
    Quadratic where the window holds at least 2 x min_samples measurements, linear from min_samples; NaN with fewer;
    robust to bad detections (`_robust_fit`).

    The factual questions are about a video seen whole, so frame t may use frames after it: at the start of a
    track a causal estimate has a few frames of evidence, a centred one a whole window."""
    n = len(z)
    pos, vel = np.full((n, 3), np.nan), np.full((n, 3), np.nan)
    seen = np.isfinite(z).all(1)
    edges = [0] + sorted({b for b in breaks if 0 < b < n}) + [n]
    for lo, hi in zip(edges[:-1], edges[1:]):
        for t in range(lo, hi):
            a, b = max(lo, t - half_window), min(hi, t + half_window + 1)
            idx = np.nonzero(seen[a:b])[0] + a
            if len(idx) < min_samples:
                continue
            pos[t], vel[t] = _robust_fit((idx - t) / fps, z[idx], min_samples)[:2]
    return pos, vel


def break_runs(breaks: list[int], n: int, gap: int) -> list[tuple[int, int]]:
    """The breaks (frames into a track of n) as runs, (first, last + 1), none more than `gap` frames after the
    last: bodies in contact for a while give a break every frame, and a run of them is one impact."""
    out = []
    for b in sorted(b for b in breaks if 0 < b < n):
        if out and b - (out[-1][1] - 1) <= gap:
            out[-1] = (out[-1][0], b + 1)
        else:
            out.append((b, b + 1))
    return out


def impacts(breaks: list[int], n: int, gap: int) -> list[int]:
    """The first frames of `break_runs`."""
    return [a for a, _ in break_runs(breaks, n, gap)]


SPEED_GRID = np.arange(0.0, 16.0, 0.02)    # m/s: the start speeds segment_motion tries (the fastest body: ~12.4)
TRUNCATE = 0.3                              # metres: segment_motion's cost of a measurement at most this far off
FLOAT_BREAK_COST = 0.1                      # m^2: floating_vz splits a line where that lowers its cost this much
FLOAT_KICK = 0.3                            # m/s: ... and its slope changes this much (the head's drift: ~0.1)


def segment_motion(z: np.ndarray, fps: int, accel: float, min_samples: int, speeds: np.ndarray = SPEED_GRID,
                   weights: np.ndarray | None = None) -> tuple[np.ndarray, float] | None:
    """The physics prior over a whole stretch between impacts: horizontal velocities [n, 3] (vz 0) for the frames
    of measured positions z [n, 3] (NaN: none), and its cost: the sum of the measurements' squared distances from
    the motion, each capped at TRUNCATE (a bad detection costs the same under every motion).

    Between impacts a body moves along a line with a known rate of change of speed `accel` (m/s^2): a ground
    vehicle without engine slows at friction's rate until it stops (< 0), one with an engine speeds up (> 0), a
    floating one holds its speed (0). So one parameter, the start speed, explains the stretch, fitted by least
    squares over `speeds` (the stop makes it non-linear) along the line of the measurements' linear fit, robust
    like `_robust_fit`. With local fits a few frames of depth noise read as a speed-up or a slow-down, and
    "accelerating" reads the change of speed over a sixth of a second. Comparing costs decides between two rates
    (an engine or none) and where an impact split the motion. `weights` [n, 2, 2] (`ray_weights`): the line's
    direction is fitted in the measurements' own metric, tight across the camera ray and loose along it (an
    unweighted line turns towards the ray: on 100 full-val videos the direction of vehicles not yet struck at the
    cut is a mean 8.4 degrees off that way, 4.9 weighted). None: fewer than 2 x min_samples measurements."""
    idx = np.nonzero(np.isfinite(z).all(1))[0]
    if len(idx) < 2 * min_samples:
        return None
    tau, xy = idx / fps, z[idx, :2]
    v0s = np.asarray(speeds, float)[:, None]
    if accel < 0:
        stop = v0s / -accel
        travel = np.where(tau < stop, v0s * tau + 0.5 * accel * tau ** 2, v0s * stop / 2)
    else:
        travel = v0s * tau + 0.5 * accel * tau ** 2
    keep = np.ones(len(idx), bool)
    for _ in range(3):
        line = _fit(tau[keep], xy[keep], False)[1] if weights is None else _weighted_line(tau[keep], xy[keep],
                                                                                            weights[idx][keep])
        u = line / max(float(np.linalg.norm(line)), 1e-9)
        along, across = xy @ u, xy @ np.array([-u[1], u[0]])
        offset = (along[keep] - travel[:, keep]).mean(1, keepdims=True)
        best = int(((along[keep] - offset - travel[:, keep]) ** 2).sum(1).argmin())
        r = np.hypot(along - offset[best] - travel[best], across - across[keep].mean())
        ok = r <= max(OUTLIER_MADS * 1.4826 * float(np.median(r[keep])), OUTLIER_FLOOR)
        if (ok == keep).all() or ok.sum() < 2 * min_samples:
            break
        keep = ok
    t = np.arange(len(z)) / fps
    speed = v0s[best, 0] + accel * t
    speed = np.maximum(speed, 0.0) if accel < 0 else speed
    return np.concatenate([speed[:, None] * u, np.zeros((len(z), 1))], 1), float((np.minimum(r, TRUNCATE) ** 2).sum())


def heading_motion(z: np.ndarray, weights: np.ndarray, fps: int, axis: np.ndarray, t0: float,
                   starts: list[tuple[float, float]], min_samples: int, heading_sd: float = 0.0
                   ) -> tuple[np.ndarray, int] | None:
    """The physics prior for a body in the air before its first impact, whose distance is the head's alone: it
    moves along its heading (the generator launches every vehicle forwards), from a start speed at frame 0 changed
    since at a known rate. The heading fixes the line that `segment_motion` has to fit from the measurements, whose
    error is mostly along the camera ray; so the speed is read where the measurements are tight (across the ray),
    and the few start speeds (`starts`: (speed at frame 0, rate in m/s^2)) compete in the measurements' own metric
    (`weights` [n, 2, 2], `ray_weights`).

    The heading is the head's, and a plane's can be tens of degrees off (read nose-on or tail-on): with
    `heading_sd` (radians) > 0 the line may turn from the axis by up to HEADING_TURN, at a cost of its turn's
    squared standard scores (a Gaussian prior around the heading), so that motion across the ray, which the
    measurements fix to centimetres, sets the direction, and the heading still sets it along the ray.

    `z` [n, 3] measured positions (NaN: none) of frames t0 * fps + 0..n-1; `axis` [3] the heading's axis (either
    way). -> (horizontal velocities [n, 3], the index of the start that explains them best); None: fewer than
    2 x min_samples measurements."""
    idx = np.nonzero(np.isfinite(z).all(1))[0]
    if len(idx) < 2 * min_samples:
        return None
    xy, W = z[idx, :2], weights[idx]
    tau = t0 + idx / fps
    base = math.atan2(axis[1], axis[0])
    turns = np.arange(-HEADING_TURN, HEADING_TURN + 1e-9, HEADING_STEP) if heading_sd > 0 else np.zeros(1)
    best = None
    for turn in turns:
        u = np.array([math.cos(base + turn), math.sin(base + turn)])
        prior = (turn / heading_sd) ** 2 if heading_sd > 0 else 0.0
        for n, (v0, rate) in enumerate(starts):
            travel = v0 * tau + 0.5 * rate * tau ** 2
            for sign in ((1.0,) if v0 == 0 and rate == 0 else (1.0, -1.0)):
                path = travel[:, None] * (sign * u)
                keep = np.ones(len(idx), bool)
                for _ in range(2):   # a bad detection out, as in segment_motion
                    x0 = np.linalg.solve(W[keep].sum(0), np.einsum("kij,kj->i", W[keep], (xy - path)[keep]))
                    r = xy - path - x0
                    d2 = np.einsum("ki,kij,kj->k", r, W, r)
                    ok = d2 <= max(9.0, 9.0 * float(np.median(d2)))
                    if (ok == keep).all() or ok.sum() < 2 * min_samples:
                        break
                    keep = ok
                cost = float(np.minimum(d2, 9.0 * max(1.0, float(np.median(d2)))).sum()) + prior
                if best is None or cost < best[0]:
                    best = cost, n, sign, u
    _, n, sign, u = best
    v0, rate = starts[n]
    speed = v0 + rate * (t0 + np.arange(len(z)) / fps)
    return np.concatenate([speed[:, None] * (sign * u), np.zeros((len(z), 1))], 1), n


PATH_MISS = 9.0     # path_motion: a stretch's median squared distance (ray metric) over this: not its motion


def path_motion(z: np.ndarray, eye: np.ndarray, fps: int, edges: list[int], accel: np.ndarray,
                accel_sd: np.ndarray, across: float, along: float, min_samples: int) -> np.ndarray | None:
    """Positions [n, 3] of the path that explains measured positions z [n, 3] (NaN: none) best, seen whole: between
    consecutive `edges` (frames, from 0 to n) a body moves at a constant acceleration, near accel[s] [S, 3] by a
    Gaussian prior of accel_sd[s] (S stretches), and at an edge its position goes on (an impact changes the
    velocity, not the position). Least squares in the measurements' metric (`ray_weights`, in 3D), robust like
    `_robust_fit`; None where a stretch holds fewer than min_samples measurements, NaN in a stretch it misses
    (their median squared Mahalanobis distance over PATH_MISS).

    Why: an aeroplane's distance is the head's alone, centimetres off across the camera ray but decimetres along
    it, and off the same way over many frames. The rays fix a path of this kind up to about one scale about the
    camera (exactly, for straight stretches), and the whole track's measurements that scale: their
    frame-to-frame noise averages out, and a stretch's bias (tumbling after an impact, the head reads a plane 10%
    too far for a second and more) is shared with the rest of the flight. `eye` [3]: the camera; `across` metres
    of standard deviation across the ray, `along` per 10 m of distance along it (place.Measurement)."""
    n, S = len(z), len(edges) - 1
    seen = np.isfinite(z).all(1)
    if any(seen[lo:hi].sum() < min_samples for lo, hi in zip(edges[:-1], edges[1:])):
        return None
    # p(f) = x0 + sum_s v_s tau_s(f) + a_s tau_s(f)^2 / 2, tau_s(f): the time spent in stretch s by frame f
    B = np.zeros((n, 1 + 2 * S))
    B[:, 0] = 1.0
    f = np.arange(n)
    for k, (lo, hi) in enumerate(zip(edges[:-1], edges[1:])):
        tau = np.clip(f - lo, 0, hi - lo) / fps
        B[:, 1 + 2 * k], B[:, 2 + 2 * k] = tau, 0.5 * tau * tau
    ray = np.where(seen[:, None], z, 0.0) - eye
    ray /= np.maximum(np.linalg.norm(ray, axis=1, keepdims=True), 1e-9)
    sd_along = along * np.maximum(np.linalg.norm(np.where(seen[:, None], z, 0.0) - eye, axis=1), 1.0) / 10.0
    W = (ray[:, :, None] * ray[:, None, :] * (1 / sd_along ** 2 - 1 / across ** 2)[:, None, None]
         + np.eye(3) / across ** 2)
    K = B.shape[1]
    prior = np.zeros((K, 3, K, 3))
    mean = np.zeros((K, 3))
    for k in range(S):
        a = 2 + 2 * k
        prior[a, :, a, :] = np.eye(3) / accel_sd[k] ** 2
        mean[a] = np.asarray(accel[k]) / accel_sd[k] ** 2
        prior[a - 1, :, a - 1, :] = np.eye(3) * 1e-4     # a stretch's speed is the measurements' (20 m/s loose)
    zs = np.where(seen[:, None], z, 0.0)
    keep = seen.copy()
    for _ in range(3):
        M = np.einsum("fk,fl,fcd->kcld", B[keep], B[keep], W[keep]) + prior
        rhs = np.einsum("fk,fcd,fd->kc", B[keep], W[keep], zs[keep]) + mean
        theta = np.linalg.solve(M.reshape(3 * K, 3 * K), rhs.reshape(3 * K)).reshape(K, 3)
        path = B @ theta
        r = path - zs
        d2 = np.einsum("fc,fcd,fd->f", r, W, r)
        ok = seen & (d2 <= 9.0 * max(1.0, float(np.median(d2[keep]))))
        if (ok == keep).all() or ok.sum() < min_samples:
            break
        keep = ok
    # a stretch whose measurements the path misses moved otherwise than its prior says (a falling plane come to
    # rest on a vehicle: full-test 000090's biplane, its median there 22 against 2 at most where the path holds)
    for lo, hi in zip(edges[:-1], edges[1:]):
        if np.median(d2[lo:hi][seen[lo:hi]]) > PATH_MISS:
            path[lo:hi] = np.nan
    return path


HEADING_TURN, HEADING_STEP = math.radians(45), math.radians(2)   # heading_motion's turns from the head's heading


def ray_weights(z: np.ndarray, eye: np.ndarray, across: float, along: float) -> np.ndarray:
    """Inverse covariances [n, 2, 2] of measured positions z [n, 3] on the ground plane: `across` metres of
    standard deviation across the camera ray, `along` per 10 m of distance along it (place.Measurement)."""
    ray = z[:, :2] - eye[:2]
    ray /= np.maximum(np.linalg.norm(ray, axis=1, keepdims=True), 1e-9)
    perp = np.stack([-ray[:, 1], ray[:, 0]], 1)
    sd_along = along * np.maximum(np.linalg.norm(z - eye, axis=1), 1.0) / 10.0
    return (ray[:, :, None] * ray[:, None, :] / sd_along[:, None, None] ** 2
            + perp[:, :, None] * perp[:, None, :] / across ** 2)


def _weighted_line(t: np.ndarray, xy: np.ndarray, W: np.ndarray) -> np.ndarray:
    """Velocity [2] of the line x0 + v t that fits positions xy [k, 2] best under inverse covariances W [k, 2, 2]."""
    J = np.zeros((len(t), 2, 4))
    J[:, :, :2] = np.eye(2)
    J[:, :, 2:] = t[:, None, None] * np.eye(2)
    A = np.einsum("kji,kjl,klm->im", J, W, J)
    b = np.einsum("kji,kjl,kl->i", J, W, xy)
    return np.linalg.lstsq(A, b, rcond=None)[0][2:]


OUTLIER_MADS, OUTLIER_FLOOR = 3.0, 0.15    # a residual above 3 robust sigmas (and 15 cm) is a bad detection


def _robust_fit(t: np.ndarray, z: np.ndarray, min_samples: int, rounds: int = 3, quadratic: bool = True
                ) -> np.ndarray:
    """`_fit` (quadratic from 2 x min_samples samples where `quadratic`, else linear) without the measurements it
    explains worst: a detection placed on a neighbour, or with its depth metres off, would otherwise bend every fit
    it is in."""
    keep = np.ones(len(t), bool)
    for _ in range(rounds):
        curved = quadratic and keep.sum() >= 2 * min_samples
        coef = _fit(t[keep], z[keep], curved)
        basis = np.stack([np.ones_like(t), t] + ([0.5 * t * t] if curved else []), 1)
        r = np.linalg.norm(z - basis @ coef, axis=1)
        ok = r <= max(OUTLIER_MADS * 1.4826 * float(np.median(r[keep])), OUTLIER_FLOOR)
        if (ok == keep).all() or ok.sum() < min_samples:
            return coef
        keep = ok
    return _fit(t[keep], z[keep], quadratic and keep.sum() >= 2 * min_samples)
