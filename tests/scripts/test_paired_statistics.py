"""python/paired_statistics.py: the bootstrap interval covers the true mean at its confidence over many seeded
trials (bimodal differences, as the study's errors are), the signed-rank test holds its level under the null and
finds a real shift, and the pooled comparison counts the layouts that separate."""

import os
import sys

import numpy

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
import paired_statistics  # noqa: E402


def bimodal(rng, n, shift_probability, shift):
    """d = 0 on most tracks, `shift` (plus noise) on a few: the shape of the study's error differences."""
    shifted = rng.random(n) < shift_probability
    return numpy.where(shifted, shift + 0.3 * rng.standard_normal(n), 0.0)


def test_bootstrap_coverage():
    rng = numpy.random.Generator(numpy.random.PCG64(11))
    trials, covered = 300, 0
    true_mean = 0.3 * -2.0
    for trial in range(trials):
        groups = [bimodal(rng, 50, 0.3, -2.0) for _ in range(3)]
        interval = paired_statistics.paired_bootstrap(groups, resamples=2000, seed=trial)
        covered += interval["ci_low"] <= true_mean <= interval["ci_high"]
    coverage = covered / trials
    assert 0.90 <= coverage <= 0.98, coverage


def test_bootstrap_is_seeded_and_stratified():
    groups = [[0.0, -1.0, -2.0], [5.0, 5.0]]
    a = paired_statistics.paired_bootstrap(groups, resamples=500, seed=3)
    b = paired_statistics.paired_bootstrap(groups, resamples=500, seed=3)
    assert a == b
    assert a["count"] == 5 and abs(a["mean"] - 7.0 / 5.0) < 1e-12
    # Stratified: layout 2 always contributes 10 to the total, so every resampled mean is at least (10 - 6) / 5.
    assert a["ci_low"] >= 4.0 / 5.0 - 1e-12


def test_signed_rank_level_and_power():
    rng = numpy.random.Generator(numpy.random.PCG64(5))
    trials = 1000
    rejections = sum(paired_statistics.signed_rank(rng.standard_normal(40))["p_less"] < 0.05 for _ in range(trials))
    assert 0.03 <= rejections / trials <= 0.07, rejections / trials
    shifted = paired_statistics.signed_rank(bimodal(rng, 200, 0.3, -2.0))
    assert shifted["p_less"] < 1e-3 and shifted["nonzero"] > 30
    assert paired_statistics.signed_rank([0.0, 0.0, 0.0]) == {"p_less": 1.0, "nonzero": 0, "median": 0.0}


def test_compare_counts_the_layouts_that_separate_on_the_pooled_side():
    rng = numpy.random.Generator(numpy.random.PCG64(2))
    groups = {"layout 1": bimodal(rng, 100, 0.5, -3.0), "layout 2": bimodal(rng, 100, 0.5, -3.0),
              "layout 3": numpy.zeros(100)}
    result = paired_statistics.compare(groups)
    assert result["pooled"]["separates"] and result["pooled"]["mean"] < 0
    assert result["layouts"]["layout 1"]["separates"] and result["layouts"]["layout 2"]["separates"]
    assert not result["layouts"]["layout 3"]["separates"]
    assert result["layouts_separating"] == 2


if __name__ == "__main__":
    for name, test in sorted(globals().items()):
        if name.startswith("test_") and callable(test):
            test()
            print(name, "ok")
