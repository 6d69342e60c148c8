"""One row of docs/validation.md: memstribo against a reference, and the rule that judges it."""

from __future__ import annotations

import math
from dataclasses import dataclass

__all__ = ["ValidationRow", "compare"]


@dataclass(frozen=True)
class ValidationRow:
    """One comparison of memstribo with a reference.

    Attributes
    ----------
    topic : str
        Section of the table ("adhesion", "contact", ...).
    quantity : str
        What is compared, e.g. "work of adhesion w12".
    reference : str
        Where the reference value comes from: "thesis 3.5 (3-34)", "Hertz closed form", ...
    reference_value : float or None
        The reference number in ``unit`` (None where the reference is a trend or an invariant).
    value : float or None
        memstribo's number in ``unit``.
    unit : str
        Unit of both numbers as displayed (e.g. "nm", "J/m^2", "" for none).
    tolerance : str
        The tolerance stated, e.g. "rel 1e-3" or "abs 0.05"; "differs (see note)" where it is not met on purpose.
    agrees : bool
        Whether the value is within the tolerance.
    command : str
        The command that prints memstribo's value (e.g. "memstribo constants --json").
    note : str
        Why the values differ, or how the comparison is made.
    shown_as_bound : bool
        The value is a residual at round-off level (reference 0, absolute tolerance): the
        table shows it as the bound it meets ("< 2e-07"), never as digits, because its
        digits depend on the platform and library versions.
    expected : {"agrees", "differs"} or None
        The verdict, fixed in the row's source: "differs" for a known disagreement (its note
        says why), "agrees" otherwise. None (the default) is "differs" when the tolerance says
        "differs (see note)", else "agrees". A test fails when a row's computed ``agrees``
        leaves its expected verdict: a row that agreed stops agreeing, or a known
        disagreement vanishes (then its note is out of date).
    band : tuple of float or None
        For a known disagreement: the range (in ``unit``) that memstribo's value is known to
        lie in; a test fails when it leaves it (the disagreement grew or shrank unnoticed).
    calibrated : str
        The fit that made memstribo reproduce this reference (a constant fitted to it, or a design
        target the model was built for); "" for a validation row. A calibrated row agrees by
        construction and is counted apart from the validated ones (issue 37).
    """

    topic: str
    quantity: str
    reference: str
    reference_value: float | None
    value: float | None
    unit: str
    tolerance: str
    agrees: bool
    command: str
    note: str = ""
    shown_as_bound: bool = False
    expected: str | None = None
    band: tuple[float, float] | None = None
    calibrated: str = ""

    def __post_init__(self):
        if self.expected is None:
            object.__setattr__(self, "expected", "differs" if self.tolerance.startswith("differs") else "agrees")
        if self.expected not in ("agrees", "differs"):
            raise ValueError(f"expected must be 'agrees' or 'differs', got {self.expected!r}")

    @property
    def as_expected(self) -> bool:
        """The computed verdict is the one fixed in the source, and a known difference stays in its band."""
        if self.agrees != (self.expected == "agrees"):
            return False
        if self.band is not None and self.value is not None:
            return self.band[0] <= self.value <= self.band[1]
        return True


def compare(topic, quantity, reference, reference_value, value, unit="", *, rtol=None, atol=None,
            command="", note="", differs: tuple[float, float] | None = None, calibrated="") -> ValidationRow:
    """Build a row, judging agreement by ``rtol`` (relative) and/or ``atol`` (absolute).

    ``differs``: a known disagreement, the band (in ``unit``) memstribo's value is known to lie in; the
    row's verdict is then "differs" whatever the value (the tests check the value stays in the band).
    ``calibrated``: the fit that made the value agree (see :class:`ValidationRow`).
    """
    if reference_value is None or value is None:
        raise ValueError("compare() needs both values; build a ValidationRow directly for trends")
    rtol_ = 0.0 if rtol is None else rtol
    atol_ = 0.0 if atol is None else atol
    agrees = math.isclose(value, reference_value, rel_tol=rtol_, abs_tol=atol_)
    parts = ([f"rel {rtol:g}"] if rtol is not None else []) + ([f"abs {atol:g}"] if atol is not None else [])
    # A residual (reference 0) that meets a non-zero absolute tolerance is round-off: show the bound.
    residual = reference_value == 0 and rtol is None and atol_ > 0 and agrees and value != 0
    return ValidationRow(topic, quantity, reference, float(reference_value), float(value), unit,
                         " or ".join(parts) or "exact", agrees, command, note, shown_as_bound=residual,
                         expected="agrees" if differs is None else "differs",
                         band=None if differs is None else (float(differs[0]), float(differs[1])),
                         calibrated=calibrated)
