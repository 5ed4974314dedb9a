"""Counterfactual imagination on an estimated scene: abduction, action, prediction (Pearl's three steps).

Re-simulating the whole video from the estimated initial state (the paper's way) lets every estimation error grow
for four seconds: the replayed factual video already differs from the one seen, in collisions nobody intervened on.
The video itself is the best evidence of what happens where an intervention does not reach, so:

- abduction: every object follows its estimated (observed) trajectory, replayed frame by frame;
- action: the intervened object is simulated from its changed initial state instead;
- prediction: the physics engine runs on; an object becomes simulated ("reached") from the frame it touches a
  reached object in the engine, or the frame of an observed collision with one (a collision that the intervention
  may have moved or removed: from there it goes on from its own state before it).

The run's collisions are the engine's impacts that involve a reached object plus the observed collisions of pairs
that the intervention had not reached by then. With no intervention this gives back the observed collisions. The
truth's counterfactuals are plain re-simulations (physics.counterfactual): with the true initial state, objects the
intervention does not reach follow their factual trajectories exactly, which is what the replay assumes.
"""

from __future__ import annotations

from typing import Sequence

import numpy as np

from dynclevr.physics import Body, ContactEvents, PhysicsParams, World, intervene
from dynclevr.scene import Collision, Scene4D


def counterfactual_run(scene: Scene4D, bodies: Sequence[Body], ids: list[int], index: int, intervention: str,
                       params: PhysicsParams, world: World) -> list[Collision] | None:
    """Collisions (object ids) of the video with `intervention` on body `index`; None if it changes nothing.

    `bodies`: every object's estimated initial state (frame 0), in the order of `ids`."""
    changed = intervene(bodies, index, intervention, params)
    if changed is None:
        return None
    cols = [scene.index(oid) for oid in ids]
    observed = {}
    for e in scene.collisions:
        if e.a in ids and e.b in ids:
            observed.setdefault(e.frame, []).append((ids.index(e.a), ids.index(e.b), e))
    world.set_bodies(changed)
    reached = np.zeros(len(ids), bool)
    reached[index] = True
    events = ContactEvents(params.merge_frames, world.masses, params.min_impact_speed)
    kept: list[Collision] = []
    for t in range(1, scene.num_frames):
        _replay(world, scene, cols, reached, t - 1)
        contacts = world.step_frame()
        # contacts of two replayed objects are the estimate's overlaps, not the engine's prediction
        contacts = {k: v for k, v in contacts.items() if reached[k[0]] or reached[k[1]]}
        events.add(t, contacts)
        for a, b in contacts:
            reached[[a, b]] = True
        for a, b, e in observed.get(t, []):
            if reached[a] or reached[b]:
                reached[[a, b]] = True
            else:
                kept.append(e)
    impacts, _ = events.done()
    out = kept + [Collision(e.frame, min(ids[e.a], ids[e.b]), max(ids[e.a], ids[e.b]), e.point, e.impulse)
                  for e in impacts]
    return sorted(out, key=lambda e: (e.frame, e.a, e.b))


def _replay(world: World, scene: Scene4D, cols: list[int], reached: np.ndarray, t: int) -> None:
    """Put every object not yet reached at its estimated state of frame t (engine and floating as estimated)."""
    follow = np.flatnonzero(~reached)
    if len(follow):
        c = np.array(cols)[follow]
        world.place(follow, scene.position[t, c], scene.orientation[t, c], scene.velocity[t, c],
                    scene.angular_velocity[t, c], scene.engine[t, c], scene.floating[t, c])
