#!/usr/bin/env python3
"""What calling semslam from Python costs: the first 1000 poses of manhattan built factor by factor in a Python
loop and solved by Gauss-Newton, against the same in C++ (bench/BuildAndSolveBaseline.cpp), side by side in one run.

Both sides start from the same plain numbers, read from the g2o file outside the timed region, and time the same
work: a prior on pose 0, one SE2 value per pose, one BetweenFactorSE2 per edge (its information matrix), then
optimize() by Gauss-Newton. Each side runs once to warm up, then REPEATS times, interleaved (a C++ run in its own
process after its own warm-up, then a Python run) so that a change in the machine's load hits both alike; the
medians and their ratio are printed, and both final chi2 must agree (the same problem was solved). Target
(issue 15): Python / C++ at most 1.5. `make bench` runs it.

    PYTHONPATH=build-bench/python /usr/bin/python3 bench/python_overhead.py \\
        --baseline build-bench/bin/semslam_build_solve_baseline [--data ../shared/data] [--poses 1000] [--repeats 5]
"""

import argparse
import json
import os
import statistics
import subprocess
import sys
import time

import numpy as np

import semslam

MANHATTAN = "vertigo/manhattan/originalDataset/g2o/manhattanOlson3500.g2o"


def plain_numbers(path, poses):
    """Vertices (key, x, y, θ) and edges (i, j, dx, dy, dθ, information) among the first `poses` poses."""
    graph = semslam.read_pose_graph(path)
    vertices = []
    for key in graph.initial.keys():
        if key < poses:
            x, y, theta = graph.initial[key].vector()
            vertices.append((key, x, y, theta))
    edges = []
    for index in range(len(graph.factors)):
        factor = graph.factors[index]
        i, j = factor.keys()
        if i < poses and j < poses:
            dx, dy, dtheta = factor.measured().vector()
            edges.append((i, j, dx, dy, dtheta, factor.noise_model().information()))
    return vertices, edges


def build_and_solve(vertices, edges):
    start = time.perf_counter()
    graph = semslam.FactorGraph()
    values = semslam.Values()
    key, x, y, theta = vertices[0]
    graph.add(semslam.PriorFactorSE2(key, semslam.SE2(x, y, theta), semslam.NoiseModel.from_sigmas([1e-6] * 3)))
    for key, x, y, theta in vertices:
        values.insert(key, semslam.SE2(x, y, theta))
    for i, j, dx, dy, dtheta, information in edges:
        graph.add(semslam.BetweenFactorSE2(i, j, semslam.SE2(dx, dy, dtheta),
                                           semslam.NoiseModel.from_information(information)))
    params = semslam.OptimizerParams()
    params.solver = semslam.Solver.GAUSS_NEWTON
    result = semslam.optimize(graph, values, params)
    return time.perf_counter() - start, result.final_chi2


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--baseline", required=True, help="the semslam_build_solve_baseline program")
    parser.add_argument("--data", default=os.path.join(os.path.dirname(__file__), "..", "..", "shared", "data"))
    parser.add_argument("--poses", type=int, default=1000)
    parser.add_argument("--repeats", type=int, default=5)
    arguments = parser.parse_args()
    path = os.path.join(arguments.data, MANHATTAN)
    if not os.path.exists(path):
        print(f"python_overhead: skipped, {path} is absent")
        return 0

    vertices, edges = plain_numbers(path, arguments.poses)
    build_and_solve(vertices, edges)  # warm-up, as the baseline does one in its process
    # Interleaved, one C++ run then one Python run, so that a change in the machine's load hits both sides alike.
    cpp_seconds, python_seconds = [], []
    for _ in range(arguments.repeats):
        baseline = json.loads(subprocess.run([arguments.baseline, path, "--poses", str(arguments.poses),
                                              "--repeats", "1"], check=True, capture_output=True, text=True).stdout)
        cpp_seconds.append(baseline["median_s"])
        seconds, python_chi2 = build_and_solve(vertices, edges)
        python_seconds.append(seconds)
    if abs(python_chi2 - baseline["final_chi2"]) > 1e-9 * max(1.0, baseline["final_chi2"]):
        print(f"python_overhead: the two sides solved different problems (chi2 {python_chi2} against "
              f"{baseline['final_chi2']})", file=sys.stderr)
        return 1
    cpp_median = statistics.median(cpp_seconds)
    python_median = statistics.median(python_seconds)
    ratio = python_median / cpp_median
    print(f"manhattan, first {len(vertices)} poses, {len(edges)} edges, built factor by factor and solved by "
          f"Gauss-Newton (final chi2 {python_chi2:.6f}), median of {arguments.repeats}:")
    print(f"  C++     {cpp_median * 1e3:8.2f} ms  (runs: " + ", ".join(f"{s * 1e3:.2f}" for s in cpp_seconds) + ")")
    print(f"  Python  {python_median * 1e3:8.2f} ms  (runs: " + ", ".join(f"{s * 1e3:.2f}" for s in python_seconds)
          + ")")
    print(f"  Python / C++ = {ratio:.3f} (target: at most 1.5)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
