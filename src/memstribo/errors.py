"""Exceptions of memstribo.

Every problem a user can cause (a bad file, a value outside its physical domain, an
unknown parameter) raises an :class:`InputError`; the CLI turns any
:class:`MemstriboError` into one clear message on stderr and exit status 2.
"""

from __future__ import annotations

import difflib
from collections.abc import Iterable


class MemstriboError(Exception):
    """Base class of every error memstribo raises on purpose."""


class InputError(MemstriboError, ValueError):
    """A value, option or parameter is outside what the model allows.

    The message names the offending input and what is allowed.
    """


class DataFileError(InputError):
    """A measurement file is missing, unreadable, corrupt or implausible."""


class ConvergenceError(MemstriboError, RuntimeError):
    """An iterative solver did not reach its tolerance.

    Solvers normally *return* an unconverged result flagged as such; this is raised
    only where a caller cannot go on without a converged answer.
    """


def did_you_mean(name: str, allowed: Iterable[str]) -> str:
    """Return ``" Did you mean 'x'?"`` for the closest allowed name, or ``""``."""
    close = difflib.get_close_matches(name, list(allowed), n=1, cutoff=0.6)
    return f" Did you mean '{close[0]}'?" if close else ""
