"""Paired comparisons of two models run on the same tracks: paper A's study (issue 12), classifier against geometric.

Per track t of layout g the paired difference is d_gt = metric(classifier) - metric(geometric). The error
differences are bimodal (most tracks pick the same history with both models, d = 0; a few pick histories a bay
apart, |d| of metres), so a Student t interval is the wrong tool there. Two tools that need no normality:

- the paired bootstrap (Efron and Tibshirani, "An Introduction to the Bootstrap", 1993, ch. 13): the mean
  difference's percentile interval over resamples of the tracks, drawn with replacement within each layout
  (stratified, so every layout keeps its number of tracks and the pooled mean weighs layouts as the data do);
- the Wilcoxon signed-rank test (scipy.stats.wilcoxon), one-sided for "the classifier lowers the metric"
  (alternative "less"), pairs with d = 0 dropped (zero_method "wilcox"), exact or normal approximation as scipy
  chooses for the sample size.

A metric separates the models on a set of tracks when the bootstrap interval excludes zero. Seeded: the same
differences and seed give the same numbers.
"""

import numpy
import scipy.stats

RESAMPLES = 10000
CONFIDENCE = 0.95


def paired_bootstrap(groups, resamples=RESAMPLES, seed=1, confidence=CONFIDENCE):
    """Mean of all differences and its percentile interval; `groups` is a list of lists of differences (one list
    per layout), resampled with replacement within each list."""
    arrays = [numpy.asarray(g, dtype=float) for g in groups if len(g) > 0]
    if not arrays:
        return {"mean": float("nan"), "ci_low": float("nan"), "ci_high": float("nan"), "count": 0}
    count = sum(a.size for a in arrays)
    rng = numpy.random.Generator(numpy.random.PCG64(seed))
    totals = numpy.zeros(resamples)
    for a in arrays:
        picks = rng.integers(0, a.size, size=(resamples, a.size))
        totals += a[picks].sum(axis=1)
    means = totals / count
    tail = (1.0 - confidence) / 2.0
    low, high = numpy.quantile(means, [tail, 1.0 - tail])
    return {"mean": float(sum(a.sum() for a in arrays) / count), "ci_low": float(low), "ci_high": float(high),
            "count": int(count)}


def signed_rank(differences):
    """One-sided Wilcoxon signed-rank p-value for 'the differences lie below zero', the pairs that differ, and the
    median difference. No pair differs: p = 1 (no evidence either way)."""
    d = numpy.asarray(differences, dtype=float)
    nonzero = int(numpy.count_nonzero(d))
    median = float(numpy.median(d)) if d.size else float("nan")
    if nonzero == 0:
        return {"p_less": 1.0, "nonzero": 0, "median": median}
    # zero_method "wilcox" drops the zero differences; dropping them here first is the same test without scipy's
    # warning that an exact p-value cannot be computed with zeros present.
    p = scipy.stats.wilcoxon(d[d != 0.0], zero_method="wilcox", alternative="less").pvalue
    return {"p_less": float(p), "nonzero": nonzero, "median": median}


def excludes_zero(interval):
    return bool(interval["ci_high"] < 0.0 or interval["ci_low"] > 0.0)


def compare(groups, seed=1):
    """Pooled and per-layout comparison of `groups` (a dict: layout -> list of paired differences).

    Returns {"pooled": {bootstrap fields, "p_less", "nonzero", "median", "separates"},
             "layouts": {layout: the same for that layout alone},
             "layouts_separating": how many layouts' intervals exclude zero on the pooled mean's side}."""
    names = sorted(groups)
    pooled = paired_bootstrap([groups[n] for n in names], seed=seed)
    pooled.update(signed_rank([d for n in names for d in groups[n]]))
    pooled["separates"] = excludes_zero(pooled)
    layouts = {}
    separating = 0
    for index, name in enumerate(names):
        result = paired_bootstrap([groups[name]], seed=seed + 1 + index)
        result.update(signed_rank(groups[name]))
        result["separates"] = excludes_zero(result)
        layouts[name] = result
        same_side = ((result["ci_high"] < 0.0 and pooled["mean"] < 0.0) or
                     (result["ci_low"] > 0.0 and pooled["mean"] > 0.0))
        separating += 1 if same_side else 0
    return {"pooled": pooled, "layouts": layouts, "layouts_separating": separating}
