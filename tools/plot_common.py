"""What qacc's plotting scripts share (plot_sweep.py, plot_crossover.py,
compose_side_by_side.py): matplotlib without a display, and the numbers of qacc's JSON
outputs, where a non-finite value is written as a string."""
import math

import matplotlib

matplotlib.use("Agg")


def num(v):
    """A JSON value as a float: numbers as they are, "inf" as infinity, anything else NaN."""
    if isinstance(v, (int, float)):
        return float(v)
    if v == "inf":
        return math.inf
    return math.nan
