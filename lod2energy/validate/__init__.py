"""Validation: val3dity-grade geometry checks, defect codes, reports, energy compliance."""
