"""The physics engine of the paper (PyBullet, REFERENCE.md section 1), shared by every stage that simulates.

- simulate (the dataset's truth) runs `simulate()` and `counterfactual()` from the sampled initial state;
- parse-scene's physics prior (REFERENCE.md section 2 item 2) steps a `World` one frame from each estimated state;
- simulate-future (item 5) runs `simulate()` / `counterfactual()` from the estimated state.
The model therefore uses the same engine as the generator, never the truth it produced.

Conventions: metres, seconds, z up; a body's position is the centre of its bounding box (which is the centre of
mass: the mesh is centred there), its orientation a quaternion (x, y, z, w), and the vehicle faces its local +x.

Forces (as in the public generator): an engine pushes along the body's heading with `engine_accel` x mass while it is
on, and (by default) only until the body's first collision with another object; a floating aeroplane gets
`floating_force` x mass upwards (10 x mass cancels gravity), a non-floating one falls.
"""

from __future__ import annotations

import functools
import hashlib
import os
import sys
from dataclasses import dataclass, replace
from typing import Sequence

import numpy as np

from dynclevr.assets import collision
from dynclevr.assets.catalogue import SUBTYPES, get_asset
from dynclevr.config import Config, ConfigError
from dynclevr.scene import INTERVENTIONS, Collision


class _Silenced:
    """Point a file descriptor at /dev/null for a block: pybullet prints a banner on stderr when imported and on
    stdout when it connects, which would garble the CLI's one-line errors and piped output."""

    def __init__(self, fd: int):
        self.fd = fd

    def __enter__(self):
        (sys.stdout if self.fd == 1 else sys.stderr).flush()
        self.saved, null = os.dup(self.fd), os.open(os.devnull, os.O_WRONLY)
        os.dup2(null, self.fd)
        os.close(null)

    def __exit__(self, *exc):
        os.dup2(self.saved, self.fd)
        os.close(self.saved)


with _Silenced(2):
    import pybullet as p


class _Client:
    """A pybullet DIRECT client: `client.fn(...)` calls `pybullet.fn(..., physicsClientId=id)`."""

    def __init__(self):
        with _Silenced(1):
            self.id = p.connect(p.DIRECT)
            # Nothing renders through these clients. Without the TinyRenderer plugin createMultiBody no longer
            # turns every convex piece into a render mesh (over a quarter of building a world); the physics never
            # reads it.
            renderer = p.loadPlugin("tinyRendererPlugin", physicsClientId=self.id)   # the loaded one's id
            if renderer >= 0:
                p.unloadPlugin(renderer, physicsClientId=self.id)

    def __getattr__(self, name):
        return functools.partial(getattr(p, name), physicsClientId=self.id)

    def disconnect(self) -> None:
        p.disconnect(physicsClientId=self.id)


# A contact whose signed distance is above this is a near miss inside Bullet's contact margin, not a touch.
TOUCH_DISTANCE = 1e-3
# Lifted this much above the floor at spawn so that no body starts in penetration (which Bullet resolves by
# pushing it up: a visible pop).
SPAWN_CLEARANCE = 1e-3


@dataclass(frozen=True)
class PhysicsParams:
    hz: int                      # physics steps per second
    fps: int                     # video frames per second; hz / fps substeps per frame
    gravity: float
    density: float
    object_friction: float
    floor_friction: float
    restitution: float
    slow_speed: float
    fast_speed: float
    engine_accel: float          # m/s^2 of engine force per unit mass
    engine_until_collision: bool  # the engine stops at the body's first collision (public generator)
    floating_force: float        # m/s^2 upwards per unit mass for floating bodies
    spinning_friction: float
    angular_damping: float       # per second: air drag on rotation
    restitution_threshold: float  # m/s: slower impacts do not bounce
    solver_iterations: int
    merge_frames: int            # contacts of the same pair within this many frames form one event
    min_impact_speed: float      # m/s of relative velocity an impact changes at least; gentler touches are no event

    @property
    def substeps(self) -> int:
        return self.hz // self.fps

    @classmethod
    def from_config(cls, cfg: Config) -> "PhysicsParams":
        ph, video = cfg["physics"], cfg["video"]
        for key in ("gravity", "slow_speed", "fast_speed", "engine_accel", "floating_force", "solver_iterations"):
            if ph[key] <= 0:
                raise ConfigError(f"'physics.{key}' = {ph[key]!r} must be positive")
        for key in ("spinning_friction", "angular_damping", "restitution_threshold", "min_impact_speed"):
            if ph[key] < 0:
                raise ConfigError(f"'physics.{key}' = {ph[key]!r} must not be negative")
        if ph["fast_speed"] <= ph["slow_speed"]:
            raise ConfigError("'physics.fast_speed' must be greater than 'physics.slow_speed'")
        merge = cfg["labels"]["collision_merge_frames"]
        if merge < 0:
            raise ConfigError(f"'labels.collision_merge_frames' = {merge!r} must not be negative")
        return cls(hz=int(ph["physics_hz"]), fps=int(video["fps"]), gravity=float(ph["gravity"]),
                   density=float(ph["density"]), object_friction=float(ph["object_friction"]),
                   floor_friction=float(ph["floor_friction"]), restitution=float(ph["restitution"]),
                   slow_speed=float(ph["slow_speed"]), fast_speed=float(ph["fast_speed"]),
                   engine_accel=float(ph["engine_accel"]), engine_until_collision=bool(ph["engine_until_collision"]),
                   floating_force=float(ph["floating_force"]), spinning_friction=float(ph["spinning_friction"]),
                   angular_damping=float(ph["angular_damping"]),
                   restitution_threshold=float(ph["restitution_threshold"]),
                   solver_iterations=int(ph["solver_iterations"]), merge_frames=int(merge),
                   min_impact_speed=float(ph["min_impact_speed"]))


@dataclass(frozen=True)
class Body:
    """One rigid vehicle: its sub-type and initial state. `mass` None means density x the asset's volume."""

    shape: str
    position: tuple[float, float, float]
    orientation: tuple[float, float, float, float] = (0.0, 0.0, 0.0, 1.0)
    velocity: tuple[float, float, float] = (0.0, 0.0, 0.0)
    angular_velocity: tuple[float, float, float] = (0.0, 0.0, 0.0)
    engine_on: bool = False
    floating: bool = False
    mass: float | None = None

    def mass_with(self, density: float) -> float:
        return self.mass if self.mass is not None else get_asset(self.shape).mass(density)

    @property
    def heading(self) -> np.ndarray:
        """Unit vector of the body's forward (+x) axis projected on the ground plane."""
        return heading(np.asarray(self.orientation, float))


@dataclass
class State:
    """The state of every body at one instant: arrays [N, ...]."""

    position: np.ndarray          # [N, 3]
    orientation: np.ndarray       # [N, 4] x, y, z, w
    velocity: np.ndarray          # [N, 3]
    angular_velocity: np.ndarray  # [N, 3]
    engine: np.ndarray            # [N] bool
    floating: np.ndarray          # [N] bool


@dataclass
class Trajectory:
    """A simulated run: arrays [T, N, ...] (frame 0 is the initial state) and the collision events, which name
    body indices (0..N-1) as `a` < `b`."""

    position: np.ndarray
    orientation: np.ndarray
    velocity: np.ndarray
    angular_velocity: np.ndarray
    acceleration: np.ndarray      # finite difference of velocity per frame
    engine: np.ndarray            # [T, N] bool
    floating: np.ndarray          # [T, N] bool
    collisions: list[Collision]
    grazes: list[Collision]       # touches too gentle to be collisions (see ContactEvents)


def catalogue_digest(cfg: Config) -> str:
    """sha256 of every sub-type's collision shape and mass: what the physics reads from the asset catalogue."""
    density = PhysicsParams.from_config(cfg).density
    h = hashlib.sha256()
    for shape in sorted(SUBTYPES):
        h.update(shape.encode())
        for piece in collision.load(shape):
            h.update(np.ascontiguousarray(piece, dtype="<f8").tobytes())
        h.update(repr(round(get_asset(shape).mass(density), 9)).encode())
    return h.hexdigest()


def ground_height(shape: str) -> float:
    """z of a body of this sub-type resting upright on the floor (its position is its bounding-box centre)."""
    return float(-min(piece[:, 2].min() for piece in collision.load(shape))) + SPAWN_CLEARANCE


def heading(quat: np.ndarray) -> np.ndarray:
    """Forward (+x) axes of quaternions [..., 4], projected on the ground and normalised: [..., 3] with z = 0."""
    x, y, z, w = np.moveaxis(np.asarray(quat, float), -1, 0)
    fwd = np.stack([1 - 2 * (y * y + z * z), 2 * (x * y + w * z), np.zeros_like(x)], axis=-1)
    n = np.linalg.norm(fwd, axis=-1, keepdims=True)
    return np.where(n > 1e-9, fwd / np.maximum(n, 1e-9), [1.0, 0.0, 0.0])


def yaw_quaternion(yaw: float) -> tuple[float, float, float, float]:
    return (0.0, 0.0, float(np.sin(yaw / 2)), float(np.cos(yaw / 2)))


class World:
    """One PyBullet DIRECT client holding a floor and the bodies; reset it cheaply with `set_state` / `set_bodies`.

    Use as a context manager (or call `close()`): the client is always disconnected.
    """

    def __init__(self, bodies: Sequence[Body], params: PhysicsParams):
        self.params = params
        self.client = _Client()
        try:
            self._setup()
            self.ids: list[int] = []
            self.shapes: list[str] = []
            self.set_bodies(bodies)
        except BaseException:
            self.close()
            raise

    def __enter__(self) -> "World":
        return self

    def __exit__(self, *exc) -> None:
        self.close()

    def close(self) -> None:
        if getattr(self, "client", None) is not None:
            self.client.disconnect()
            self.client = None

    def _setup(self) -> None:
        c, pp = self.client, self.params
        self._shapes: dict[str, int] = {}
        c.setGravity(0, 0, -pp.gravity)
        c.setTimeStep(1.0 / pp.hz)
        c.setPhysicsEngineParameter(
            numSubSteps=0,                 # exactly one 1/hz step per stepSimulation: we step substeps ourselves
            numSolverIterations=pp.solver_iterations,
            deterministicOverlappingPairs=1,  # contact order independent of memory layout: same seed, same bytes
            # Split impulse keeps penetration recovery out of the velocities: resolving overlap does not add
            # energy, so resting and sliding contacts do not jitter or pop.
            useSplitImpulse=1, splitImpulsePenetrationThreshold=-0.01,
            # Below this closing speed contacts do not bounce: no micro-bounces of a body sliding on the floor.
            restitutionVelocityThreshold=pp.restitution_threshold,
        )
        self.floor = c.createMultiBody(0, c.createCollisionShape(p.GEOM_PLANE))
        self._dynamics(self.floor, pp.floor_friction)

    def _dynamics(self, uid: int, friction: float) -> None:
        # Bullet multiplies the two bodies' friction (and restitution) coefficients in a contact.
        # No linear damping: free flight and floating hold their speed; only friction and collisions slow a body.
        # Some angular damping (air drag): an aeroplane spun by an impact in the air stops tumbling after a while.
        # Rolling friction is meaningless for sliding boxes; a little spinning friction lets a body that was set
        # spinning by an impact come to rest instead of pirouetting on one contact point forever.
        # contactProcessingThreshold 0: only touching points (not near misses in the margin) reach the solver,
        # so bodies passing close by are not pulled into sticky contacts.
        self.client.changeDynamics(uid, -1, lateralFriction=friction, restitution=self.params.restitution,
                                   rollingFriction=0.0, spinningFriction=self.params.spinning_friction,
                                   linearDamping=0.0, angularDamping=self.params.angular_damping,
                                   contactProcessingThreshold=0.0)

    def _shape(self, shape: str) -> int:
        """The sub-type's compound of convex pieces (dynclevr/assets/collision.py), made once per world."""
        if shape not in self._shapes:
            collision.load(shape)   # checks the file against the mesh
            self._shapes[shape] = self.client.createCollisionShape(p.GEOM_MESH, fileName=str(collision.path(shape)))
        return self._shapes[shape]

    def set_bodies(self, bodies: Sequence[Body]) -> None:
        """Make the world hold exactly `bodies` in their initial states: a clean start, as in a new World.

        A run must be a pure function of its initial state. Bodies left over from an earlier run keep contact
        manifolds and warm-start impulses, removed-and-recreated ones get new ids and a new pair order, and
        Bullet's saveState / restoreState does not restore free rigid bodies exactly: each made reruns drift. So
        the world is emptied (resetSimulation, which keeps the client: a new connection costs 20 ms) and rebuilt."""
        c = self.client
        shapes = [b.shape for b in bodies]
        for s in shapes:
            if s not in SUBTYPES:
                raise KeyError(f"unknown sub-type {s!r}")
        if self.ids:
            c.resetSimulation()
            self._setup()
        self.masses = [b.mass_with(self.params.density) for b in bodies]
        # Maximal coordinates: a free rigid body (btRigidBody) rather than a one-link multibody; faster and the
        # plain rigid-body model the generator uses.
        self.ids = [c.createMultiBody(m, self._shape(s), useMaximalCoordinates=True)
                    for s, m in zip(shapes, self.masses)]
        for uid in self.ids:
            self._dynamics(uid, self.params.object_friction)
        self.shapes = shapes
        self._index = {uid: i for i, uid in enumerate(self.ids)}
        self.set_state(np.array([b.position for b in bodies], float).reshape(-1, 3),
                       np.array([b.orientation for b in bodies], float).reshape(-1, 4),
                       np.array([b.velocity for b in bodies], float).reshape(-1, 3),
                       np.array([b.angular_velocity for b in bodies], float).reshape(-1, 3),
                       np.array([b.engine_on for b in bodies], bool), np.array([b.floating for b in bodies], bool))

    def set_state(self, position, orientation, velocity, angular_velocity=None, engine=None, floating=None) -> None:
        """Teleport every body to a state (arrays [N, ...]); engine / floating None keep the current flags.

        Cheapest reset, for stepping along a track (parse-scene's prior): contact caches survive, so results can
        differ slightly from a clean start; use `set_bodies` where a run must not depend on the one before."""
        n = len(self.ids)
        angular_velocity = np.zeros((n, 3)) if angular_velocity is None else angular_velocity
        for i, uid in enumerate(self.ids):
            self.client.resetBasePositionAndOrientation(uid, tuple(map(float, position[i])),
                                                        tuple(map(float, orientation[i])))
            self.client.resetBaseVelocity(uid, tuple(map(float, velocity[i])), tuple(map(float, angular_velocity[i])))
        if engine is not None:
            self.engine = np.array(engine, bool).reshape(n)
        if floating is not None:
            self.floating = np.array(floating, bool).reshape(n)

    def place(self, which: Sequence[int], position, orientation, velocity, angular_velocity, engine, floating
              ) -> None:
        """Teleport the bodies `which` (indices) to states (arrays [len(which), ...]) with their engine and floating
        flags; the others keep theirs (a counterfactual replay moves only the bodies it has not reached)."""
        for k, i in enumerate(which):
            uid = self.ids[i]
            self.client.resetBasePositionAndOrientation(uid, tuple(map(float, position[k])),
                                                        tuple(map(float, orientation[k])))
            self.client.resetBaseVelocity(uid, tuple(map(float, velocity[k])), tuple(map(float, angular_velocity[k])))
        self.engine[list(which)] = np.asarray(engine, bool)
        self.floating[list(which)] = np.asarray(floating, bool)

    def step_frame(self) -> dict[tuple[int, int], tuple[tuple[float, float, float], float]]:
        """Advance one video frame (hz / fps physics steps) under the engine and floating forces.

        Returns the object pairs (i < j, body indices) that touched during the frame, each with the first contact
        point and the summed normal impulse (N s). Floor contacts are not collisions and are left out."""
        pp, cid, floor, index, masses = self.params, self.client.id, self.floor, self._index, self.masses
        dt = 1.0 / pp.hz
        touched: dict[tuple[int, int], list] = {}
        # Per-substep work is the hot loop of every stage that simulates: plain pybullet calls, no numpy in it.
        engine = [(self.ids[i], (pp.engine_accel * masses[i], 0.0, 0.0))
                  for i, on in enumerate(self.engine.tolist()) if on]
        floating = [(self.ids[i], (0.0, 0.0, pp.floating_force * masses[i]))
                    for i, on in enumerate(self.floating.tolist()) if on]
        for _ in range(pp.substeps):
            for uid, force in engine:
                # In the body frame at its centre of mass: along its nose, and no torque.
                p.applyExternalForce(uid, -1, force, (0.0, 0.0, 0.0), p.LINK_FRAME, physicsClientId=cid)
            for uid, force in floating:
                # Upwards, at the centre of mass (no torque): needs the current position.
                pos = p.getBasePositionAndOrientation(uid, physicsClientId=cid)[0]
                p.applyExternalForce(uid, -1, force, pos, p.WORLD_FRAME, physicsClientId=cid)
            p.stepSimulation(physicsClientId=cid)
            for pt in p.getContactPoints(physicsClientId=cid):
                # Most points are the floor's: the cheapest test first.
                if pt[1] == floor or pt[2] == floor or pt[8] > TOUCH_DISTANCE:
                    continue
                a, b = index[pt[1]], index[pt[2]]
                key = (a, b) if a < b else (b, a)
                if key in touched:
                    touched[key][1] += pt[9] * dt
                else:
                    touched[key] = [tuple(map(float, pt[5])), pt[9] * dt]
            if engine and pp.engine_until_collision and touched:
                # The engine stops at the body's first collision: an impact as ContactEvents counts it, not a graze.
                hit = {i for (a, b), (_, imp) in touched.items() if imp * (1 / masses[a] + 1 / masses[b])
                       >= pp.min_impact_speed for i in (a, b)}
                if hit:
                    self.engine[list(hit)] = False
                    engine = [(uid, f) for uid, f in engine if index[uid] not in hit]
        return {k: (v[0], float(v[1])) for k, v in touched.items()}

    def gaps(self, within: float) -> dict[tuple[int, int], float]:
        """Body pairs (i < j) whose hulls are closer than `within` metres now, with their signed distance."""
        out: dict[tuple[int, int], float] = {}
        for i in range(len(self.ids)):
            for j in range(i + 1, len(self.ids)):
                pts = self.client.getClosestPoints(self.ids[i], self.ids[j], within)
                if pts:
                    out[(i, j)] = float(min(pt[8] for pt in pts))
        return out

    def states(self) -> State:
        c = self.client
        pose = [c.getBasePositionAndOrientation(u) for u in self.ids]
        vel = [c.getBaseVelocity(u) for u in self.ids]
        n = len(self.ids)
        return State(np.array([q[0] for q in pose], float).reshape(n, 3),
                     np.array([q[1] for q in pose], float).reshape(n, 4),
                     np.array([v[0] for v in vel], float).reshape(n, 3),
                     np.array([v[1] for v in vel], float).reshape(n, 3),
                     self.engine.copy(), self.floating.copy())


class ContactEvents:
    """Merges per-frame contacts into impacts: the same pair touching again within `merge` frames of its last
    contact is the same event (its impulse adds up); the event's frame and point are those of the first contact.
    An event whose impulse changes the pair's relative velocity by less than `min_speed` (impulse / reduced mass)
    is a graze or a resting contact in a pile, not an impact, and is dropped."""

    def __init__(self, merge: int, masses: Sequence[float], min_speed: float):
        self.merge, self.masses, self.min_speed = merge, list(masses), min_speed
        self.events: list[Collision] = []
        self._open: dict[tuple[int, int], tuple[Collision, int]] = {}

    def add(self, frame: int, contacts: dict) -> None:
        for (a, b), (point, impulse) in sorted(contacts.items()):
            ev, last = self._open.get((a, b), (None, -10**9))
            if ev is not None and frame - last <= self.merge:
                ev.impulse += impulse
            else:
                ev = Collision(frame, a, b, tuple(round(x, 6) for x in point), impulse)
                self.events.append(ev)
            self._open[(a, b)] = (ev, frame)

    def done(self) -> tuple[list[Collision], list[Collision]]:
        """(impacts, grazes), each sorted by frame."""
        impacts, grazes = [], []
        for e in self.events:
            ma, mb = self.masses[e.a], self.masses[e.b]
            e.impulse = round(float(e.impulse), 6)
            (impacts if e.impulse * (ma + mb) / (ma * mb) >= self.min_speed else grazes).append(e)
        return tuple(sorted(x, key=lambda e: (e.frame, e.a, e.b)) for x in (impacts, grazes))


def simulate(bodies: Sequence[Body], params: PhysicsParams, frames: int, world: World | None = None,
             record: bool = True) -> Trajectory:
    """Run `frames` frames (frame 0 = the initial state) from `bodies`' initial states.

    Collision events name body indices (0..N-1). `world`: a World to reuse (it is reset to `bodies`);
    `record` False skips the state arrays (counterfactual runs need only the events)."""
    own = world is None
    world = World(bodies, params) if own else world
    try:
        if not own:
            world.set_bodies(bodies)
        events = ContactEvents(params.merge_frames, world.masses, params.min_impact_speed)
        n = len(bodies)
        T = frames if record else 1
        pos, quat = np.zeros((T, n, 3)), np.zeros((T, n, 4))
        vel, ang = np.zeros((T, n, 3)), np.zeros((T, n, 3))
        eng, flo = np.zeros((T, n), bool), np.zeros((T, n), bool)

        def keep(t):
            s = world.states()
            pos[t], quat[t], vel[t], ang[t], eng[t], flo[t] = (s.position, s.orientation, s.velocity,
                                                               s.angular_velocity, s.engine, s.floating)

        keep(0)
        for t in range(1, frames):
            events.add(t, world.step_frame())
            if record:
                keep(t)
    finally:
        if own:
            world.close()
    acc = np.zeros_like(vel)
    if T > 1:
        acc[1:] = np.diff(vel, axis=0) * params.fps
        acc[0] = acc[1]
    return Trajectory(pos, quat, vel, ang, acc, eng, flo, *events.done())


def intervene(bodies: Sequence[Body], index: int, intervention: str, params: PhysicsParams) -> list[Body] | None:
    """The initial state with one change to body `index`, or None when the change would change nothing.

    static: at rest, engine off. slow / fast: params.slow_speed / fast_speed along its heading (vertical velocity
    kept: a falling aeroplane still falls). accelerating: engine on. floating (aeroplanes only): the floating force
    on from the start, at the height where it is (aeroplanes spawn in the air, so it simply stops falling)."""
    if intervention not in INTERVENTIONS:
        raise ValueError(f"unknown intervention {intervention!r}; use one of {', '.join(INTERVENTIONS)}")
    b = bodies[index]
    v = np.asarray(b.velocity, float)
    if intervention == "static":
        new = replace(b, velocity=(0.0, 0.0, 0.0), angular_velocity=(0.0, 0.0, 0.0), engine_on=False)
    elif intervention in ("slow", "fast"):
        speed = params.slow_speed if intervention == "slow" else params.fast_speed
        h = b.heading * speed
        new = replace(b, velocity=(float(h[0]), float(h[1]), float(v[2])))
    elif intervention == "accelerating":
        new = replace(b, engine_on=True)
    else:
        if SUBTYPES[b.shape][0] != "aeroplane":
            return None
        new = replace(b, floating=True)
    if _same(new, b):
        return None
    out = list(bodies)
    out[index] = new
    return out


def _same(a: Body, b: Body) -> bool:
    return (a.engine_on == b.engine_on and a.floating == b.floating
            and np.allclose(a.velocity, b.velocity, atol=1e-6)
            and np.allclose(a.angular_velocity, b.angular_velocity, atol=1e-6))


def counterfactual(bodies: Sequence[Body], index: int, intervention: str, params: PhysicsParams, frames: int,
                   world: World | None = None) -> Trajectory | None:
    """A re-simulation with one intervention on body `index`, its collisions and grazes only (None if the
    intervention changes nothing)."""
    changed = intervene(bodies, index, intervention, params)
    if changed is None:
        return None
    return simulate(changed, params, frames, world=world, record=False)
