#!/usr/bin/env python3
"""The measured constants of the KITTI tracking converter (docs/datasets.md, "KITTI tracking"), reproduced.

  odometry  ORB-SLAM's per-frame relative-pose error on KITTI odometry 00 (evo-testdata: KITTI_00_ORB against
            KITTI_00_gt): E_k = (G_{k-1}^-1 G_k)^-1 (O_{k-1}^-1 O_k) in body axes (x forward, y left, z up), its
            SE(3) log (translation, rotation vector); per component the mean, std, robust std (1.4826 MAD) and the
            stated sigma = 95 % quantile of |e - median e| / 1.96 (kKittiOrbSlamSigmas).
  sigma     sigma(r) = a + b r, radial and lateral, from the CSV files that `semslam convert kitti-tracking ...
            --matches-out FILE` writes (Car detections matched to Car labels): per 10 m range bin the stated sigma
            (95 % quantile of |e - median| / 1.96), then the count-weighted least-squares line through the bins, and
            the residual of each bin against the line (kKittiRadialSigma, kKittiLateralSigma). Lateral pools the
            horizontal and vertical components across the ray.
  scores    per detector class, the score threshold that maximises F1 of the matched detections (any kind but
            false-positive) against the false positives, over every detection in the CSV files (convert with
            thresholds of -100 so that none is dropped); kKittiDefaultScoreThresholds.
  confusion the matched detections' counts, rows the label's class (Car, Pedestrian incl. Person_sitting,
            Cyclist), columns the detected class, over the CSV files, at the given thresholds.

Usage:
  python3 python/kitti_tracking_fit.py --evo ../shared/data/evo-testdata [--matches DIR_OR_FILES...]
                                        [--thresholds CAR PED CYC]
Only numpy is needed.
"""

import argparse
import csv
import glob
import os

import numpy as np

CLASSES = ["Car", "Pedestrian", "Cyclist"]
LABEL_CLASS = {"Car": 0, "Pedestrian": 1, "Person_sitting": 1, "Cyclist": 2}
S = np.eye(4)
S[:3, :3] = [[0, 0, 1], [-1, 0, 0], [0, -1, 0]]


def read_kitti(path):
    a = np.loadtxt(path)
    t = np.zeros((len(a), 4, 4))
    t[:, :3, :] = a.reshape(-1, 3, 4)
    t[:, 3, 3] = 1.0
    return t


def so3_log(r):
    c = min(1.0, max(-1.0, (np.trace(r) - 1.0) / 2.0))
    th = np.arccos(c)
    w = np.array([r[2, 1] - r[1, 2], r[0, 2] - r[2, 0], r[1, 0] - r[0, 1]]) / 2.0
    return w if th < 1e-9 else w * th / np.sin(th)


def se3_log(t):
    w = so3_log(t[:3, :3])
    th = np.linalg.norm(w)
    wx = np.array([[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]])
    if th < 1e-9:
        v = np.eye(3) + wx / 2.0
    else:
        v = np.eye(3) + (1 - np.cos(th)) / th**2 * wx + (th - np.sin(th)) / th**3 * wx @ wx
    return np.concatenate([np.linalg.solve(v, t[:3, 3]), w])


def stated_sigma(x):
    x = np.asarray(x)
    return np.quantile(np.abs(x - np.median(x)), 0.95) / 1.96


def odometry(evo):
    g = read_kitti(os.path.join(evo, "KITTI_00_gt.txt"))
    o = read_kitti(os.path.join(evo, "KITTI_00_ORB.txt"))
    si = np.linalg.inv(S)
    e = []
    for k in range(1, len(g)):
        gk = np.linalg.inv(g[k - 1]) @ g[k]
        ok = np.linalg.inv(o[k - 1]) @ o[k]
        e.append(se3_log(S @ np.linalg.inv(gk) @ ok @ si))
    e = np.array(e)
    print(f"odometry: {len(e)} one-frame pairs of KITTI_00_ORB against KITTI_00_gt (body axes)")
    print(f"{'component':>10} {'mean':>11} {'std':>11} {'robust std':>11} {'stated':>11}")
    for i, name in enumerate(["x [m]", "y [m]", "z [m]", "rx [rad]", "ry [rad]", "rz [rad]"]):
        x = e[:, i]
        robust = 1.4826 * np.median(np.abs(x - np.median(x)))
        print(f"{name:>10} {x.mean():11.3g} {x.std():11.4g} {robust:11.4g} {stated_sigma(x):11.4g}")


def read_matches(paths):
    files = []
    for p in paths:
        files += sorted(glob.glob(os.path.join(p, "*.csv"))) if os.path.isdir(p) else [p]
    rows = []
    for f in files:
        with open(f, newline="") as handle:
            rows += list(csv.DictReader(handle))
    return files, rows


def sigma_fit(rows):
    cars = [r for r in rows if r["class"] == "Car" and r["label_type"] == "Car"]
    rng = np.array([float(r["range"]) for r in cars])
    radial = np.array([float(r["radial"]) for r in cars])
    lateral = np.array([float(r["lateral"]) for r in cars])
    vertical = np.array([float(r["vertical"]) for r in cars])
    print(f"\nsigma(r): {len(cars)} Car detections matched to Car labels")
    fits = {}
    for name, components in (("radial", [radial]), ("lateral", [lateral, vertical])):
        centres, sigmas, counts = [], [], []
        print(f"{name:>8} {'bin [m]':>9} {'count':>6} {'mean':>8} {'robust std':>10} {'stated':>8}")
        for lo in range(0, 80, 10):
            sel = (rng >= lo) & (rng < lo + 10)
            if sel.sum() < 20:
                continue
            x = np.concatenate([c[sel] for c in components])
            centres.append(rng[sel].mean())
            sigmas.append(stated_sigma(x))
            counts.append(sel.sum())
            robust = 1.4826 * np.median(np.abs(x - np.median(x)))
            print(f"{'':>8} {lo:4d}-{lo + 10:<4d} {sel.sum():6d} {x.mean():8.3f} {robust:10.3f} {sigmas[-1]:8.3f}")
        w = np.array(counts, dtype=float)
        a_mat = np.stack([np.ones(len(centres)), np.array(centres)], axis=1)
        sw = np.sqrt(w)
        coef, *_ = np.linalg.lstsq(a_mat * sw[:, None], np.array(sigmas) * sw, rcond=None)
        fits[name] = coef
        res = np.array(sigmas) - a_mat @ coef
        print(f"{'':>8} fit sigma_{name} = {coef[0]:.4f} + {coef[1]:.5f} r; bin residuals "
              + " ".join(f"{x:+.3f}" for x in res))
    return fits


def thresholds(rows):
    print("\nscore thresholds (F1 of matched against false positives, every score):")
    best = []
    for c in CLASSES:
        sel = [r for r in rows if r["class"] == c and r["kind"] in ("landmark", "moving", "false-positive",
                                                                       "slow-track", "other-vehicle")]
        score = np.array([float(r["score"]) for r in sel])
        positive = np.array([r["kind"] != "false-positive" for r in sel])
        order = np.argsort(-score, kind="stable")
        s, p = score[order], positive[order]
        tp = np.cumsum(p)
        fp = np.cumsum(~p)
        f1 = 2 * tp / (tp + fp + p.sum())
        i = int(np.argmax(f1))
        best.append(s[i])
        print(f"  {c:10s} {len(s):6d} detections ({p.sum()} matched), scores {s.min():.2f} .. {s.max():.2f} "
              f"(median {np.median(s):.2f}); best F1 {f1[i]:.3f} at score >= {s[i]:.3f}: {tp[i]} matched and "
              f"{fp[i]} false positives kept")
    return best


def confusion(rows, cut):
    counts = np.zeros((3, 3), dtype=int)
    for r in rows:
        if r["label_type"] in LABEL_CLASS and float(r["score"]) >= cut[CLASSES.index(r["class"])]:
            counts[LABEL_CLASS[r["label_type"]], CLASSES.index(r["class"])] += 1
    print(f"\nconfusion counts at thresholds {cut} (rows true Car, Pedestrian, Cyclist; columns detected):")
    for row in counts:
        print("  " + " ".join(f"{x:6d}" for x in row))
    off = counts.sum() - np.trace(counts)
    print(f"  misclassification (off + 1) / (total + 3) = {(off + 1) / (counts.sum() + 3):.5f}")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--evo", help="the evo-testdata folder (odometry covariance)")
    parser.add_argument("--matches", nargs="*", default=[], help="--matches-out CSV files, or folders of them")
    parser.add_argument("--thresholds", nargs=3, type=float, help="thresholds for the confusion counts")
    args = parser.parse_args()
    if args.evo:
        odometry(args.evo)
    if args.matches:
        files, rows = read_matches(args.matches)
        print(f"\n{len(rows)} detections from {len(files)} files")
        sigma_fit(rows)
        best = thresholds(rows)
        confusion(rows, args.thresholds if args.thresholds else best)


if __name__ == "__main__":
    main()
