"""The shared reference harness can fail: it reports the worst points with the source."""

from __future__ import annotations

import math

import pytest

from harness import Reference, assert_close, assert_mpmath_equal, check_reference


def test_check_reference_passes_and_fails_naming_the_source():
    # sqrt against exact squares (exact values): passes at 1e-15, a wrong row fails
    ref = Reference(name="sqrt", source="exact squares", points=((4.0,), (9.0,)),
                    expected=(2.0, 3.0), rtol=1e-15)
    check_reference(math.sqrt, ref)
    wrong = Reference(name="sqrt", source="a deliberately wrong table", points=((4.0,),),
                      expected=(2.1,), rtol=1e-6)
    with pytest.raises(AssertionError, match="a deliberately wrong table"):
        check_reference(math.sqrt, wrong)
    with pytest.raises(ValueError, match="1 points, 2 expected"):
        Reference(name="x", source="s", points=((1.0,),), expected=(1.0, 2.0), rtol=0.0)


def test_assert_close_and_mpmath_equal():
    assert_close([1.0, 2.0], [1.0, 2.0 + 1e-13], rtol=1e-12, source="identity")
    with pytest.raises(AssertionError, match="source: identity"):
        assert_close([1.0], [1.1], rtol=1e-3, source="identity")
    mpmath = pytest.importorskip("mpmath")
    assert_mpmath_equal(math.exp, mpmath.exp, [(0.5,), (2.0,)], rtol=1e-14)
    with pytest.raises(AssertionError, match="mpmath at 30 digits"):
        assert_mpmath_equal(math.sin, mpmath.cos, [(0.5,)], rtol=1e-6)
