#!/usr/bin/python3
"""The three numbers issue 42 compares odometries by, against a reference.

  scripts/odometry_scores.py ESTIMATE.txt REFERENCE.txt

Both files are KITTI poses, one per scan, line k = scan k. Prints:
- ATE: the RMSE of the positions after the best-fit SE(3) alignment
  (Umeyama without scale; mlndt_eval --alignment=se3 gives the same);
- per-step error: median and RMSE over k of the error of the motion
  k-1 -> k against the reference's (translation [m], rotation [deg]);
- end drift: the error of the motion first -> last scan against the
  reference's, translation [m] and as % of the reference's path length.
"""
import sys

import numpy as np


def load(path):
    rows = np.loadtxt(path, ndmin=2)
    poses = np.tile(np.eye(4), (len(rows), 1, 1))
    poses[:, :3, :] = rows.reshape(-1, 3, 4)
    return poses


def motion_error(estimated, reference):
    e = np.linalg.inv(reference) @ estimated
    r = e[:3, :3]
    sine = np.linalg.norm([r[2, 1] - r[1, 2], r[0, 2] - r[2, 0], r[1, 0] - r[0, 1]]) / 2
    angle = np.degrees(np.arctan2(sine, (np.trace(r) - 1) / 2))
    return np.linalg.norm(e[:3, 3]), angle


def ate_se3(estimate, reference):
    p = estimate[:, :3, 3]
    q = reference[:, :3, 3]
    mp, mq = p.mean(0), q.mean(0)
    u, _, vt = np.linalg.svd((q - mq).T @ (p - mp))
    s = np.eye(3)
    s[2, 2] = np.sign(np.linalg.det(u @ vt))
    r = u @ s @ vt
    aligned = (r @ (p - mp).T).T + mq
    return np.sqrt(np.mean(np.sum((aligned - q) ** 2, axis=1)))


def main(argv):
    if len(argv) != 3:
        sys.exit(__doc__)
    estimate, reference = load(argv[1]), load(argv[2])
    if len(estimate) != len(reference):
        sys.exit(f"{len(estimate)} estimated poses, {len(reference)} reference poses")
    steps = np.array([
        motion_error(np.linalg.inv(estimate[k - 1]) @ estimate[k],
                     np.linalg.inv(reference[k - 1]) @ reference[k])
        for k in range(1, len(estimate))
    ])
    path = np.sum(np.linalg.norm(np.diff(reference[:, :3, 3], axis=0), axis=1))
    end_m, end_deg = motion_error(np.linalg.inv(estimate[0]) @ estimate[-1],
                                  np.linalg.inv(reference[0]) @ reference[-1])
    print(f"ATE (SE3) rmse {ate_se3(estimate, reference):.3f} m")
    print(f"per-step error median {100 * np.median(steps[:, 0]):.2f} cm, "
          f"{np.median(steps[:, 1]):.3f} deg; rmse "
          f"{100 * np.sqrt(np.mean(steps[:, 0] ** 2)):.2f} cm, "
          f"{np.sqrt(np.mean(steps[:, 1] ** 2)):.3f} deg")
    print(f"end drift {end_m:.3f} m, {end_deg:.2f} deg = "
          f"{100 * end_m / path:.2f} % of {path:.1f} m")


if __name__ == "__main__":
    main(sys.argv)
