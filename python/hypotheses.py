"""Reads hypotheses.jsonl, the per-step record of a hybrid-belief run (semslam run --method hybrid).

Each line is one time step k. A component's association history beta_1:k is stored once, as a tree: the component
has "beta" (its beta_k, the landmark id of each detection of step k, -1 for a dropped detection) and "ancestor"
(the index of the component of line k - 1 it branched from, -1 on the first line). An association-marginal entry
names the first component with its history ("component"). This module follows the ancestors back.

    lines = hypotheses.read("RUN/hypotheses.jsonl")
    hypotheses.history(lines, k, i)            # beta_1:k of component i of line k: [[ids of step 0], ...]
    hypotheses.association_marginal(lines, k)  # [(beta_1:k, P(beta_1:k | H_k)), ...], heaviest first
"""

import json


def read(path):
    """Every line of hypotheses.jsonl, as dicts, in step order."""
    with open(path) as f:
        return [json.loads(line) for line in f if line.strip()]


def history(lines, k, component):
    """beta_1:k of `component` of line k: a list of k + 1 lists of landmark ids (one per step)."""
    steps = []
    while k >= 0:
        record = lines[k]["components"][component]
        steps.append(record["beta"])
        component = record["ancestor"]
        k -= 1
    steps.reverse()
    return steps


def association_marginal(lines, k):
    """Eq. 8 of paper A at step k: (history, weight) pairs, heaviest first, as the line lists them."""
    return [(history(lines, k, a["component"]), a["weight"]) for a in lines[k]["association_marginal"]]
