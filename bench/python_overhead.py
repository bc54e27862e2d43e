#!/usr/bin/env python3
"""What calling semslam from Python costs: the first 1000 poses of manhattan built factor by factor in a Python
loop and solved by Gauss-Newton, against the same in C++ (bench/BuildAndSolveBaseline.cpp), side by side in one run.

Both sides start from the same plain numbers, read from the g2o file outside the timed region, and time the same
work: a prior on pose 0, one SE2 value per pose, one BetweenFactorSE2 per edge (its information matrix), then
optimize() by Gauss-Newton. In each of ROUNDS rounds the C++ program runs REPEATS times in one process (after a
warm-up run), then Python REPEATS times here (after a warm-up run), each run timed in its thread's CPU time; the
medians over all runs and their ratio are printed, and both final chi2 must agree (the same problem was solved).
Target (issue 15): Python / C++ at most 1.5. `make bench` runs it.

    PYTHONPATH=build-bench/python /usr/bin/python3 bench/python_overhead.py \\
        --baseline build-bench/bin/semslam_build_solve_baseline [--data ../shared/data] [--poses 1000] \\
        [--repeats 5] [--rounds 3] [--per-call]
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
    """(seconds building, seconds solving, final chi2) of one run, in this thread's CPU time (as the baseline: on a
    shared virtual machine wall time also counts other tenants' steal, which hits two runs unequally)."""
    start = time.thread_time()
    graph = semslam.FactorGraph()
    values = semslam.Values()
    key, x, y, theta = vertices[0]
    graph.add(semslam.PriorFactorSE2(key, semslam.SE2(x, y, theta), semslam.NoiseModel.from_sigmas([1e-6] * 3)))
    for key, x, y, theta in vertices:
        values.insert(key, semslam.SE2(x, y, theta))
    for i, j, dx, dy, dtheta, information in edges:
        graph.add(semslam.BetweenFactorSE2(i, j, semslam.SE2(dx, dy, dtheta),
                                           semslam.NoiseModel.from_information(information)))
    built = time.thread_time()
    params = semslam.OptimizerParams()
    params.solver = semslam.Solver.GAUSS_NEWTON
    result = semslam.optimize(graph, values, params)
    return built - start, time.thread_time() - built, result.final_chi2


def per_call_microseconds(edges, calls=20000, blocks=5):
    """What each call of the loop costs on its own: the best of `blocks` blocks of `calls` calls, in µs per call."""
    information = edges[0][5]
    noise = semslam.NoiseModel.from_information(information)
    measured = semslam.SE2(1.0, 2.0, 0.3)
    graph = semslam.FactorGraph()
    factor = semslam.BetweenFactorSE2(0, 1, measured, noise)
    values = semslam.Values()
    keys = iter(range(10 ** 9))
    cases = {
        "NoiseModel.from_information(3x3)": lambda: semslam.NoiseModel.from_information(information),
        "NoiseModel.isotropic(3, s)": lambda: semslam.NoiseModel.isotropic(3, 1.0),
        "BetweenFactorSE2(i, j, z, noise)": lambda: semslam.BetweenFactorSE2(0, 1, measured, noise),
        "SE2(x, y, theta)": lambda: semslam.SE2(1.0, 2.0, 0.3),
        "FactorGraph.add(factor)": lambda: graph.add(factor),
        "Values.insert(key, SE2)": lambda: values.insert(next(keys), measured),
        "a bound call doing nothing (SE2.x)": measured.x,
    }
    costs = {}
    for name, call in cases.items():
        best = float("inf")
        for _ in range(blocks):
            start = time.thread_time()
            for _ in range(calls):
                call()
            best = min(best, (time.thread_time() - start) / calls)
        costs[name] = best * 1e6
    return costs


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--baseline", required=True, help="the semslam_build_solve_baseline program")
    parser.add_argument("--data", default=os.path.join(os.path.dirname(__file__), "..", "..", "shared", "data"))
    parser.add_argument("--poses", type=int, default=1000)
    parser.add_argument("--repeats", type=int, default=5, help="runs per side in each round")
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--per-call", action="store_true", help="also time each call of the loop on its own")
    arguments = parser.parse_args()
    path = os.path.join(arguments.data, MANHATTAN)
    if not os.path.exists(path):
        print(f"python_overhead: skipped, {path} is absent")
        return 0

    vertices, edges = plain_numbers(path, arguments.poses)
    # Rounds of blocks: the C++ program runs REPEATS times in one process (after its own warm-up), then Python
    # REPEATS times in this one (after a warm-up run: the first run after a process start is disturbed), so that
    # a change in the machine's load over the rounds hits both sides alike.
    cpp, python = {"total": [], "build": [], "solve": []}, {"total": [], "build": [], "solve": []}
    for _ in range(arguments.rounds):
        baseline = json.loads(subprocess.run([arguments.baseline, path, "--poses", str(arguments.poses),
                                              "--repeats", str(arguments.repeats)], check=True, capture_output=True,
                                             text=True).stdout)
        cpp["total"] += baseline["seconds"]
        cpp["build"] += baseline["build_seconds"]
        cpp["solve"] += baseline["solve_seconds"]
        build_and_solve(vertices, edges)
        for _ in range(arguments.repeats):
            build, solve, python_chi2 = build_and_solve(vertices, edges)
            python["total"].append(build + solve)
            python["build"].append(build)
            python["solve"].append(solve)
    if abs(python_chi2 - baseline["final_chi2"]) > 1e-9 * max(1.0, baseline["final_chi2"]):
        print(f"python_overhead: the two sides solved different problems (chi2 {python_chi2} against "
              f"{baseline['final_chi2']})", file=sys.stderr)
        return 1
    median = {side: {part: statistics.median(runs) for part, runs in times.items()}
              for side, times in (("C++", cpp), ("Python", python))}
    print(f"manhattan, first {len(vertices)} poses, {len(edges)} edges, built factor by factor and solved by "
          f"Gauss-Newton (final chi2 {python_chi2:.6f}), medians of {arguments.rounds} rounds x {arguments.repeats} "
          "runs per side [ms of thread CPU time]:")
    print(f"  {'':8}{'total':>9}{'build':>9}{'solve':>9}   runs (total, in order)")
    for side, times in (("C++", cpp), ("Python", python)):
        m = median[side]
        print(f"  {side:8}{m['total'] * 1e3:9.2f}{m['build'] * 1e3:9.2f}{m['solve'] * 1e3:9.2f}   "
              + ", ".join(f"{s * 1e3:.2f}" for s in times["total"]))
    ratio = median["Python"]["total"] / median["C++"]["total"]
    print(f"  Python / C++ = {ratio:.3f} (target: at most 1.5)")
    if arguments.per_call:
        print("  per call, best of 5 blocks of 20,000 [µs of thread CPU time]:")
        for name, microseconds in per_call_microseconds(edges).items():
            print(f"    {name:38}{microseconds:6.2f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
