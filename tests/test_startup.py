"""Start-up cost: ``lod2energy --help`` stays light because of where imports are.

Modules import what they use at their heads; the CLI builds its parser from modules whose heads
import nothing heavy, and each command imports its modules when it runs (the CLI's lazy entry).
:func:`head_imports` follows module-level imports through the project's modules; the probes run
a fresh interpreter and list the heavy top-level packages in ``sys.modules`` afterwards. No timings.
"""
from __future__ import annotations

import ast
import json
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]

# packages that cost 0.1-1.5 CPU s to import and that only some commands or code paths need
HEAVY = {"scipy", "shapely", "trimesh", "pyproj", "jsonschema", "jsonschema_rs", "eppy", "manifold3d",
         "pyvista", "jinja2", "matplotlib", "tqdm", "networkx", "numpy"}


def loaded_after(code: str) -> set[str]:
    """The :data:`HEAVY` packages in ``sys.modules`` after running ``code`` in a new interpreter."""
    probe = textwrap.dedent(code) + textwrap.dedent(f"""
        import json as _json, sys as _sys
        print(_json.dumps(sorted({{m.split(".")[0] for m in _sys.modules}} & set({sorted(HEAVY)!r}))))
    """)
    out = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, check=True)
    return set(json.loads(out.stdout.strip().splitlines()[-1]))


def test_importing_the_cli_loads_nothing_heavy():
    assert loaded_after("import lod2energy.cli") == set()


@pytest.mark.parametrize("argv", [["--help"], ["export", "--help"], ["validate", "--help"], ["view", "--help"],
                                  ["validate"]])
def test_help_and_usage_errors_load_nothing_heavy(argv):
    loaded = loaded_after(f"""
        import contextlib, io
        from lod2energy.cli import main
        with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(io.StringIO()):
            try:
                main({argv!r})
            except SystemExit:
                pass
    """)
    # the parser is built from lod2energy.config and argparse alone: not even numpy
    assert loaded == set(), loaded


@pytest.mark.parametrize("module", ["lod2energy.geometry", "lod2energy.polymesh", "lod2energy.semantics",
                                    "lod2energy.thermal", "lod2energy.validate.report", "lod2energy.repair",
                                    "lod2energy.pipeline", "lod2energy.geometry.snap"])
def test_core_modules_import_scipy_on_first_use(module):
    """scipy (0.4 s) is imported where a path needs it, which validation mostly does not (the
    one exception to imports at the top besides optional dependencies, see test_architecture)."""
    loaded = loaded_after(f"import {module}")
    assert not loaded & {"scipy", "trimesh", "pyproj", "jsonschema", "eppy", "matplotlib", "pyvista"}, (module, loaded)


def test_snapping_loads_no_scipy():
    loaded = loaded_after("""
        import numpy as np
        from lod2energy.geometry import snap_map
        from lod2energy.geometry.snap import snap_points
        p = np.array([[0.0, 0.0, 0.0], [0.0, 0.0, 1e-4], [5.0, 0.0, 0.0]])
        assert snap_map(p, 1e-3).tolist() == [0, 0, 2] and snap_points(p, 1e-3).tolist() == [0, 0, 2]
    """)
    assert "numpy" in loaded and "scipy" not in loaded, loaded


def test_the_probe_sees_a_package_once_it_is_used():
    # the control: the constrained Delaunay triangulation uses scipy's Qhull
    loaded = loaded_after("""
        import numpy as np
        from lod2energy.geometry import constrained_delaunay
        constrained_delaunay(np.array([[0.0, 0.0], [2.0, 0.0], [2.0, 1.0], [0.0, 1.0]]), np.array([4]))
    """)
    assert {"numpy", "scipy"} <= loaded


def head_imports(module: str) -> set[str]:
    """Top-level packages imported, directly or through project modules, by the module-level
    statements of ``module`` (a function's body is not followed: the CLI's lazy entry)."""
    seen, todo, outside = set(), [module], set()
    while todo:
        mod = todo.pop()
        if mod in seen:
            continue
        seen.add(mod)
        path = _path_of(mod)
        if path is None:
            continue
        parts = mod.split(".")
        # importing a.b.c runs a and a.b first
        todo.extend(".".join(parts[:i]) for i in range(1, len(parts)))
        is_pkg = path.name == "__init__.py"
        for node in _module_level(ast.parse(path.read_text(encoding="utf-8")).body):
            if isinstance(node, ast.Import):
                names = [a.name for a in node.names]
            elif node.level:
                base = parts if is_pkg else parts[:-1]
                base = base[:len(base) - (node.level - 1)]
                src = ".".join(base + ([node.module] if node.module else []))
                names = [src] + [f"{src}.{a.name}" for a in node.names]
            else:
                names = [node.module] + [f"{node.module}.{a.name}" for a in node.names]
            for n in names:
                if n.split(".")[0] in ("lod2energy", "exporters"):
                    todo.append(n)
                elif n.split(".")[0] != "__future__":
                    outside.add(n.split(".")[0])
    return outside


def _path_of(mod: str) -> Path | None:
    parts = mod.split(".")
    if parts[:2] == ["lod2energy", "exporters"]:
        parts = ["exporters"] + parts[2:]
    elif parts[:2] == ["lod2energy", "templates"]:
        return None
    base = ROOT.joinpath(*parts)
    for p in (base / "__init__.py", base.with_suffix(".py")):
        if p.is_file():
            return p
    return None  # a name inside a module (from m import name)


def _module_level(body: list[ast.stmt]):
    """Import statements run when the module is imported (in ``if`` / ``try`` too; not under
    ``if TYPE_CHECKING``)."""
    for node in body:
        if isinstance(node, (ast.Import, ast.ImportFrom)):
            yield node
        elif isinstance(node, ast.If):
            if not (isinstance(node.test, ast.Name) and node.test.id == "TYPE_CHECKING"):
                yield from _module_level(node.body)
                yield from _module_level(node.orelse)
        elif isinstance(node, ast.Try):
            for b in (node.body, node.orelse, node.finalbody, *[h.body for h in node.handlers]):
                yield from _module_level(b)


def test_the_cli_head_imports_nothing_heavy():
    # by where the imports are: the parser's modules import no heavy package at their heads
    # (each command's modules are imported by the command when it runs)
    assert head_imports("lod2energy.cli") & (HEAVY | {"pymeshlab", "PIL"}) == set()


def test_head_imports_follow_project_modules():
    # the control: the pipeline's head reaches numpy and shapely through the modules it imports
    assert {"numpy", "shapely"} <= head_imports("lod2energy.pipeline")
    assert "pymeshlab" not in head_imports("lod2energy.pipeline")  # only the alpha-wrap child loads it


def test_one_blas_thread_loads_no_scipy_and_still_limits_it():
    # numpy already loaded: threadpoolctl limits it; scipy's OpenBLAS, loaded later, reads the environment
    code = """
        import os
        for v in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
            os.environ.pop(v, None)
        import numpy, sys
        from lod2energy.run.blas_threads import one_blas_thread
        one_blas_thread()
        assert "scipy" not in sys.modules
        import scipy.linalg
        from threadpoolctl import threadpool_info
        assert {i["num_threads"] for i in threadpool_info() if i["user_api"] == "blas"} == {1}, threadpool_info()
    """
    assert "scipy" in loaded_after(code)
