"""Exact reuse of a case's value across constant samples that differ only in constants the case does not read.

The calibration predicts every row for each prior sample of the bond energies; a pull-off force or a Hertz contact
reads none of them, and recomputing it per sample cost minutes (issue 40: ``validate-lab`` <= 2 min). The first
evaluation of a case runs on a :class:`ReadRecorder` of its parameters, which notes every name the case reads; a
later sample whose values of exactly those names are the same (the same parameter set name too) takes the stored
value. The path a case takes depends only on what it read, so equal reads give the same result, bit for bit.
Anything that reads the whole mapping (iteration, ``updated``, ``to_dict``) makes the key all the values.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from memstribo.parameters import Parameters

__all__ = ["ReadRecorder", "read_key"]


class ReadRecorder(Parameters):
    """The same parameters, noting the names read (``read``) or that all were read (``read_all``)."""

    def __init__(self, params: Parameters):
        super().__init__(params._values, params._sources, params.name)
        self.read: set[str] = set()
        self.read_all = False

    def __getitem__(self, name: str) -> Any:
        self.read.add(name)
        return super().__getitem__(name)

    def __iter__(self):
        self.read_all = True
        return super().__iter__()

    def updated(self, overrides, origin: str = "user override") -> Parameters:
        self.read_all = True
        return super().updated(overrides, origin)

    def to_dict(self) -> dict[str, Any]:
        self.read_all = True
        return super().to_dict()

    def names(self) -> tuple[str, ...] | None:
        """The names read, sorted; None where the whole mapping was read."""
        return None if self.read_all else tuple(sorted(self.read))


def _canonical(value) -> Any:
    if isinstance(value, np.ndarray):
        return (value.dtype.str, value.shape, value.tobytes())
    return repr(value)


def read_key(params: Parameters, names: tuple[str, ...] | None) -> tuple:
    """The values of ``names`` in ``params`` (all of them where ``names`` is None), with the set's name: a key."""
    names = tuple(sorted(params._values)) if names is None else names
    return (params.name,) + tuple((n, _canonical(params._values.get(n))) for n in names)
