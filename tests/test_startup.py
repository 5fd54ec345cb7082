"""Start-up cost (issue 13): the CLI and the core modules import no heavy package eagerly.

Each probe runs in a fresh interpreter and lists the heavy top-level packages in
``sys.modules`` afterwards. A module-level ``import scipy`` (or shapely, trimesh, ...)
re-added on the import path of the CLI or of the pipeline makes these fail. No timings.
"""
from __future__ import annotations

import json
import subprocess
import sys
import textwrap

import pytest

# packages that cost 0.1-1.5 CPU s to import and that only some commands or code paths need
HEAVY = {"scipy", "shapely", "trimesh", "pyproj", "jsonschema", "fastjsonschema", "eppy", "manifold3d",
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
    """shapely is imported at the top of the modules that use it (validation needs it anyway);
    scipy (0.4 s) only where a path needs it, which validation mostly does not."""
    loaded = loaded_after(f"import {module}")
    assert not loaded & {"scipy", "trimesh", "pyproj", "jsonschema", "eppy", "jinja2",
                         "matplotlib", "pyvista"}, (module, loaded)


def test_the_probe_sees_a_package_once_it_is_used():
    # the control: the constrained Delaunay triangulation tries scipy's Qhull first, so after
    # one CDT scipy is loaded (snapping no longer needs scipy: lod2energy.geometry.pairs)
    loaded = loaded_after("""
        import numpy as np
        from lod2energy.geometry import constrained_delaunay
        constrained_delaunay(np.array([[0.0, 0.0], [2.0, 0.0], [2.0, 1.0], [0.0, 1.0]]), np.array([4]))
    """)
    assert {"numpy", "scipy"} <= loaded


def test_snapping_loads_no_scipy():
    loaded = loaded_after("""
        import numpy as np
        from lod2energy.geometry import snap_map
        from lod2energy.geometry.snap import snap_points
        p = np.array([[0.0, 0.0, 0.0], [0.0, 0.0, 1e-4], [5.0, 0.0, 0.0]])
        assert snap_map(p, 1e-3).tolist() == [0, 0, 2] and snap_points(p, 1e-3).tolist() == [0, 0, 2]
    """)
    assert "numpy" in loaded and "scipy" not in loaded, loaded


def test_one_blas_thread_loads_no_scipy_and_still_limits_it():
    # numpy already loaded: threadpoolctl limits it; scipy's OpenBLAS, loaded later, reads the environment
    code = """
        import os
        for v in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
            os.environ.pop(v, None)
        import numpy, sys
        from lod2energy.threads import one_blas_thread
        one_blas_thread()
        assert "scipy" not in sys.modules
        import scipy.linalg
        from threadpoolctl import threadpool_info
        assert {i["num_threads"] for i in threadpool_info() if i["user_api"] == "blas"} == {1}, threadpool_info()
    """
    assert "scipy" in loaded_after(code)
