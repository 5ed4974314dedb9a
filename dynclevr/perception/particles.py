"""The particle filter: the paper's future work (section 2.2: "particle filtering"), `parser.filter = "particle"`.

The single-particle prior (tracker.py) keeps one Gaussian per object around the engine's prediction, and a
collision the engine did not predict has to be caught by a hand-made manoeuvre rule. Here each object carries
`particles` hypotheses. What is uncertain in a discrete way, whether the object was just hit by something the
engine did not see, is sampled; the rest, position and velocity given that history, is Gaussian and exact (a
Rao-Blackwellised particle filter: each particle is a Kalman filter, so few particles suffice and none drift):
- predict: every particle's mean moves with the physics engine's step of the object's estimate (the same PE as the
  single filter: mu_t - S_{t-1} is applied to all, so contacts and forces move every hypothesis) plus its own
  offset at its own velocity; its covariance grows by the process noise, and for a share `jump_rate` of the
  particles by `maneuver_speed` in velocity as well (the hypothesis "hit just now");
- weight: the detection's predictive likelihood under each particle (Gaussian, tight across the camera ray and
  loose along it) mixed with a flat outlier share `outlier_rate` (a neighbour's detection, a bad depth); then
  each particle's Kalman update;
- resample (systematic) when the effective sample size falls below half.
The estimate is the weighted mean. A missed frame is a prediction alone, so the hypotheses spread through an
occlusion and the detection that ends it picks among them.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

H = np.eye(3, 6)


@dataclass
class ParticleCloud:
    mean: np.ndarray      # [N, 6]: position, velocity per particle
    cov: np.ndarray       # [N, 6, 6]
    weight: np.ndarray    # [N], sums to 1

    @classmethod
    def start(cls, position: np.ndarray, cov: np.ndarray, n: int) -> "ParticleCloud":
        """Every particle at the first measurement with the filter's initial covariance."""
        mean = np.tile(np.concatenate([position, np.zeros(3)]), (n, 1))
        return cls(mean, np.tile(cov, (n, 1, 1)), np.full(n, 1.0 / n))

    def estimate(self) -> np.ndarray:
        return self.weight @ self.mean

    def predict(self, drift_position: np.ndarray, drift_velocity: np.ndarray, dt: float, p: dict,
                rng: np.random.Generator) -> None:
        """Move every particle with the engine's step of the estimate (`drift_*`: mu_t - estimate_{t-1}) and its
        own offset from the estimate at its own velocity; grow the covariances, some by a manoeuvre."""
        n = len(self.weight)
        v_mean = self.weight @ self.mean[:, 3:]
        self.mean[:, :3] += drift_position + (self.mean[:, 3:] - v_mean) * dt
        self.mean[:, 3:] += drift_velocity
        F = np.eye(6)
        F[:3, 3:] = dt * np.eye(3)
        Q = np.diag([p["process_position"] ** 2] * 3 + [p["process_velocity"] ** 2] * 3)
        self.cov = F @ self.cov @ F.T + Q
        kicked = rng.random(n) < p["jump_rate"]
        self.cov[kicked, 3:, 3:] += p["maneuver_speed"] ** 2 * np.eye(3)

    def update(self, z: np.ndarray, R: np.ndarray, outlier_rate: float, rng: np.random.Generator) -> float:
        """Weight by the measurement, then the particles' Kalman updates. Returns the measurement's
        Mahalanobis^2 under the cloud's best explanation (large: a manoeuvre or an outlier)."""
        S = self.cov[:, :3, :3] + R                              # [N, 3, 3]
        S_inv = np.linalg.inv(S)
        innov = z - self.mean[:, :3]                             # [N, 3]
        m2 = np.einsum("ni,nij,nj->n", innov, S_inv, innov)
        like = np.exp(-0.5 * m2) / np.sqrt(np.linalg.det(2 * np.pi * S))
        # the flat outlier level: the Gaussian's density 3 sigma out
        like = (1 - outlier_rate) * like + outlier_rate * np.exp(-4.5) / np.sqrt(np.linalg.det(2 * np.pi * S))
        w = self.weight * like
        self.weight = w / w.sum() if w.sum() > 0 else np.full(len(w), 1.0 / len(w))
        gain = self.cov[:, :, :3] @ S_inv                        # [N, 6, 3]
        self.mean = self.mean + np.einsum("nij,nj->ni", gain, innov)
        self.cov = (np.eye(6) - gain @ H) @ self.cov
        if 1.0 / np.sum(self.weight ** 2) < len(self.weight) / 2:
            self._resample(rng)
        return float(m2.min())

    def shift_velocity(self, dv: np.ndarray) -> None:
        self.mean[:, 3:] += dv

    def _resample(self, rng: np.random.Generator) -> None:
        n = len(self.weight)
        positions = (rng.random() + np.arange(n)) / n
        idx = np.minimum(np.searchsorted(np.cumsum(self.weight), positions), n - 1)
        self.mean, self.cov = self.mean[idx], self.cov[idx]
        self.weight = np.full(n, 1.0 / n)
