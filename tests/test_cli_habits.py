"""CLI habits: help on every option, val3dity's option spellings, one -j default."""
from __future__ import annotations

import argparse

import pytest

from lod2energy.cli import build_parser


def subparsers() -> dict[str, argparse.ArgumentParser]:
    p = build_parser()
    (sub,) = [a for a in p._actions if isinstance(a, argparse._SubParsersAction)]
    return dict(sub.choices)


@pytest.mark.parametrize("command", sorted(subparsers()))
def test_every_option_has_help(command):
    missing = [a.option_strings or [a.dest] for a in subparsers()[command]._actions
               if not (a.help and a.help.strip()) and a.help is not argparse.SUPPRESS]
    assert missing == []


def test_the_help_rule_sees_an_option_without_help():
    p = argparse.ArgumentParser()
    p.add_argument("--bare")
    assert [a.dest for a in p._actions if not a.help] == ["bare"]


@pytest.mark.parametrize("command", ["validate", "repair", "export"])
@pytest.mark.parametrize("val3dity, ours", [("--planarity_d2p_tol", "planarity_d2p_tol"),
                                            ("--planarity_n_tol", "planarity_n_tol"),
                                            ("--overlap_tol", "overlap_tol"), ("--snap_tol", "snap_tol")])
def test_val3dity_spellings_are_aliases(command, val3dity, ours):
    args = {"validate": ["validate", "f.json"], "repair": ["repair", "f.json", "-o", "o.json"],
            "export": ["export", "f.json", "-o", "o"]}[command]
    a = build_parser().parse_args(args + [val3dity, "0.5"])
    b = build_parser().parse_args(args + ["--" + ours.replace("_", "-"), "0.5"])
    assert getattr(a, ours) == getattr(b, ours) == 0.5


def test_one_jobs_default_for_every_command():
    defaults = {name: p.get_default("jobs") for name, p in subparsers().items()
                if any(a.dest == "jobs" for a in p._actions)}
    assert set(defaults) >= {"repair", "export"} and set(defaults.values()) == {None}  # None: all cores
