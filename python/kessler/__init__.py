"""Kessler from Python: decks, runs and their results (docs/python.md).

    import kessler
    deck = kessler.deck("examples/sphere-plate.yaml", {"bodies.0.mesh_size": "1 mm"})
    result = kessler.run(deck, out="results/sp", threads=2)
    result.analysis["holes"][0]["diameter_m"]
    result.points(-1)["pressure"]          # numpy array, read from the HDF5 when asked for

The runs are the `kessler` program's own (the same library): the same checks and error messages,
the same run folder, restartable from the command line or from here.
"""

from ._core import _kessler
from .results import Results
from .runs import bench, deck, restart, run, verify

InputError = _kessler.InputError
NumericalError = _kessler.NumericalError
Error = _kessler.Error
Deck = _kessler.Deck


def methods():
    """The methods this build runs (solver.method): otm, sph, rkpm."""
    return list(_kessler.methods())


def program():
    """The path of the kessler program this module was built with."""
    return _kessler.program()


__all__ = ["Deck", "Error", "InputError", "NumericalError", "Results", "bench", "deck", "methods", "program",
           "restart", "run", "verify"]
