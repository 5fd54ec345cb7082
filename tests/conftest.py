"""Shared pytest fixtures: paths to the shared data, canonical buildings.

Shared data live next to the repository (``../shared``); tests that need it skip when it
is absent. Helpers may append fixtures here; keep each one small and documented.
"""
from __future__ import annotations

import sys
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[1]
SHARED = REPO.parent / "shared"
DATA = SHARED / "data"
VAL3DITY_TESTS = DATA / "val3dity-tests"
REFERENCE = SHARED / "reference"

# make ``import factories`` work from any test module
sys.path.insert(0, str(Path(__file__).resolve().parent))


def shared_path(*parts: str) -> Path:
    """Path under ``../shared/data``; skips the calling test when it does not exist."""
    p = DATA.joinpath(*parts)
    if not p.exists():
        pytest.skip(f"shared data not available: {p.relative_to(REPO.parent)}")
    return p


@pytest.fixture(scope="session")
def val3dity_suite() -> Path:
    """val3dity's test-data folder (skips when absent)."""
    if not (VAL3DITY_TESTS / "EXPECTED_RESULTS.json").exists():
        pytest.skip("val3dity test data not available (../shared/data/val3dity-tests)")
    return VAL3DITY_TESTS


@pytest.fixture(scope="session")
def denhaag_path() -> Path:
    """Den Haag tile 01 (CityJSON, 844 buildings with BuildingParts)."""
    return shared_path("denhaag", "DenHaag_01.city.json")


@pytest.fixture
def box_building():
    """A valid 10 x 8 x 6 m box with semantics."""
    from factories import box
    return box()


@pytest.fixture
def gabled_building():
    """A valid gabled house with semantics."""
    from factories import gabled_house
    return gabled_house()
