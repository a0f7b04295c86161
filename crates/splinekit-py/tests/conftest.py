"""Fixtures shared by the test files."""

import pytest


@pytest.fixture
def heart():
    """The document of a blending spline of the heart curve: eight cubic Bézier local
    curves blended by ERBS (a fresh dict for each test)."""
    return {
        "type": "blending_spline",
        "model": {"type": "heart"},
        "local_curves": 8,
        "local": {"type": "bezier", "degree": 3},
        "bfunction": {"type": "erbs"},
    }
