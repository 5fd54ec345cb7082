"""The one driver (lod2energy.run.driver): a command is a tuple of stages run in order over one Run;
every command of the CLI and the CFD case is such a declaration; errors become exit codes."""
from __future__ import annotations

import argparse
import importlib
import os

import pytest

from lod2energy import cli
from lod2energy.errors import ExportError, InputError, ParameterError
from lod2energy.run.driver import Command, Run, drive, execute
from lod2energy.safe_write import UnsafeWriteError


def _args(**kw) -> argparse.Namespace:
    return argparse.Namespace(quiet=True, verbose=False, **kw)


def test_stages_run_in_order_share_the_run_and_stop_ends_the_command():
    seen = []

    def first(run: Run) -> None:
        seen.append(("first", run.args.x))
        run.made["folder"] = run.scratch()
        assert os.path.isdir(run.made["folder"])
        run.worse(1)

    def second(run: Run) -> None:
        seen.append(("second", run.made["folder"] is not None))
        run.stop(2)

    def never(run: Run) -> None:
        seen.append(("never", None))

    run = execute(Command("t", (first, second, never), writers=lambda a: ("stl",)), _args(x=7))
    assert seen == [("first", 7), ("second", True)]
    assert run.code == 2 and run.writers == ("stl",)
    assert not os.path.exists(run.made["folder"])  # the scratch folder goes with the command


def test_worse_only_raises_the_code():
    def stage(run: Run) -> None:
        run.worse(1)
        run.worse(0)

    assert execute(Command("t", (stage,)), _args()).code == 1


@pytest.mark.parametrize("error, code", [
    (ParameterError("bad option"), 2), (InputError("bad file"), 2), (UnsafeWriteError("over an input"), 2),
    (ExportError("self-check failed"), 1), (FileNotFoundError(2, "No such file", "x.json"), 2),
])
def test_an_error_is_one_line_and_an_exit_code(error, code, capsys):
    def stage(run: Run) -> None:
        raise error

    assert drive(Command("t", (stage,)), _args()) == code
    err = capsys.readouterr().err
    assert err.startswith("lod2energy: error: ") and err.count("\n") == 1 and "Traceback" not in err


def test_done_in_unless_quiet(capsys):
    cmd = Command("t", (lambda run: None,))
    assert drive(cmd, argparse.Namespace(quiet=False, verbose=False)) == 0
    assert capsys.readouterr().err.startswith("done in ")
    assert drive(cmd, _args()) == 0
    assert capsys.readouterr().err == ""


@pytest.mark.parametrize("name", sorted(cli._DECLARED))
def test_every_cli_command_is_a_declared_command(name):
    module, attr = cli._DECLARED[name]
    cmd = getattr(importlib.import_module(module), attr)
    assert isinstance(cmd, Command) and cmd.name == name and cmd.stages
    assert all(callable(s) for s in cmd.stages)


def test_the_cfd_case_is_a_declared_command():
    from lod2energy.cfd.__main__ import CFD
    assert isinstance(CFD, Command) and CFD.writers(_args()) == ("cfd",)


def test_the_declared_writers_are_loaded_before_the_first_stage():
    import subprocess
    import sys
    import textwrap
    probe = textwrap.dedent("""
        import argparse, sys
        from lod2energy.run.driver import Command, execute
        seen = []
        stage = lambda run: seen.append("lod2energy.exporters.stl.writer" in sys.modules)
        execute(Command("none", (stage,)), argparse.Namespace())
        execute(Command("stl", (stage,), writers=lambda a: ("stl",)), argparse.Namespace())
        print(seen)
    """)
    out = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "[False, True]"
