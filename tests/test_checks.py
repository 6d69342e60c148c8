"""Tests of the shared input checks (memstribo.checks)."""

import re

import numpy as np
import pytest

from memstribo.checks import as_array, as_positive_scalar
from memstribo.errors import InputError


# --- as_array: accepted values ------------------------------------------------------------------

def test_scalar_gives_0d_float_array():
    out = as_array(3, "load", "N", positive=True)
    assert isinstance(out, np.ndarray) and out.ndim == 0 and out.dtype == float and out == 3.0


def test_array_keeps_shape_and_is_float():
    value = np.arange(1, 7, dtype=np.int32).reshape(2, 3)
    out = as_array(value, "gap", "m", positive=True)
    assert out.shape == (2, 3) and out.dtype == float
    np.testing.assert_array_equal(out, value)
    assert as_array([1.0, 2.0], "gap", "m").tolist() == [1.0, 2.0]


def test_bounds_accept_what_they_allow():
    assert as_array(-1.0, "x", "m") == -1.0                       # no sign rule: any finite value
    assert as_array(0.0, "x", "m", nonnegative=True) == 0.0       # >= 0 allows zero
    np.testing.assert_array_equal(as_array([0.0, 2.0], "x", "m", nonnegative=True), [0.0, 2.0])
    assert as_array(1e-300, "x", "m", positive=True) == 1e-300


# --- as_array: refused values and their messages ---------------------------------------------------

@pytest.mark.parametrize("value", ["abc", None, [1.0, [2.0, 3.0]], {"a": 1}, 1j])
def test_non_numeric(value):
    # None converts to NaN: refused as not finite, with the value shown
    with pytest.raises(InputError, match=r"^gap must be (numeric and )?positive and finite \[m\], got "):
        as_array(value, "gap", "m", positive=True)


@pytest.mark.parametrize("value", [np.nan, np.inf, -np.inf])
@pytest.mark.parametrize("rule, allowed", [({}, "finite"), ({"nonnegative": True}, ">= 0 and finite"),
                                           ({"positive": True}, "positive and finite")])
def test_not_finite(value, rule, allowed):
    with pytest.raises(InputError, match=re.escape(f"depth must be {allowed} [m], got {value!r}.")):
        as_array(value, "depth", "m", **rule)


def test_zero_and_negative():
    with pytest.raises(InputError, match=re.escape("load must be positive and finite [N], got 0.0.")):
        as_array(0.0, "load", "N", positive=True)
    with pytest.raises(InputError, match=re.escape("load must be positive and finite [N], got -2.")):
        as_array(-2, "load", "N", positive=True)
    with pytest.raises(InputError, match=re.escape("strain must be >= 0 and finite, got -0.1.")):
        as_array(-0.1, "strain", nonnegative=True)  # dimensionless: no unit brackets
    # positive wins over nonnegative: zero is refused
    with pytest.raises(InputError, match="positive"):
        as_array(0.0, "load", "N", positive=True, nonnegative=True)


def test_array_message_counts_and_shows_the_first_offender():
    with pytest.raises(InputError, match=re.escape(
            "heights must be positive and finite [m], but 2 of 4 values are not (the first: -1.0).")):
        as_array([1.0, -1.0, 0.0, 3.0], "heights", "m", positive=True)
    with pytest.raises(InputError, match=re.escape("x must be finite [m], but 1 of 3 values are not (the first: nan).")):
        as_array(np.array([0.0, np.nan, 1.0]), "x", "m")
    # a large array is summarised, not printed whole
    big = np.ones(100_000)
    big[-1] = 0.0
    with pytest.raises(InputError) as info:
        as_array(big, "gap", "m", positive=True)
    assert "1 of 100000" in str(info.value) and len(str(info.value)) < 200


def test_input_error_is_a_value_error():
    with pytest.raises(ValueError):
        as_array(np.nan, "x")


# --- as_positive_scalar -------------------------------------------------------------------------

def test_positive_scalar_accepts():
    out = as_positive_scalar(np.float32(2.5), "step", "m")
    assert type(out) is float and out == 2.5
    assert as_positive_scalar(np.array(3.0), "step", "m") == 3.0
    assert as_positive_scalar(7, "step") == 7.0


@pytest.mark.parametrize("value", [0.0, -1e-9, np.nan, np.inf, None, "abc", [1.0, 2.0], np.array([1.0])])
def test_positive_scalar_refuses(value):
    with pytest.raises(InputError, match=re.escape(f"step must be a positive, finite number [m], got {value!r}.")):
        as_positive_scalar(value, "step", "m")


def test_positive_scalar_without_unit():
    with pytest.raises(InputError, match=re.escape("ratio must be a positive, finite number, got 0.")):
        as_positive_scalar(0, "ratio")
