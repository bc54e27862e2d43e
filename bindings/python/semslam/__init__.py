"""semslam: SLAM with ambiguous data association, from Python.

A thin layer over the C++ library (the compiled module ``semslam._semslam``):
numpy arrays in and out, C++ errors raised as Python exceptions
(``semslam.InputError`` names the file and line). docs/python.md has the
whole API and a runnable example.

    import semslam
    result = semslam.run("mm-nh", "log.jsonl", no_covariances=True)
    result.metrics["ate_rmse"], result.trajectory  # N x 3 (x, y, theta)
"""

from ._semslam import *  # noqa: F401,F403  (the module's public names: geometry, graph, solve, files, run)
from ._semslam import __version__  # noqa: F401
