"""Architecture rules: no import circle, no writer importing the repair package, caches in one
place, imports at the top, no oversized module, and docs/architecture.md naming what exists.

The module graph is built from the source with :mod:`ast`, counting function-local imports
too: a local import that only hides a circle is still a circle.
"""
from __future__ import annotations

import ast
import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
PACKAGES = {"lod2energy": ROOT / "lod2energy", "exporters": ROOT / "exporters"}

MAX_LINES = 600
# Modules still over MAX_LINES, each with the cap it must not grow past until it is split
# (issue 14: the EnergyPlus package, the CityJSON writer/reader, the spine's writers pass)
EXEMPT_SIZE: dict[str, int] = {}


def _modules() -> dict[str, Path]:
    out = {}
    for pkg, base in PACKAGES.items():
        for p in sorted(base.rglob("*.py")):
            rel = p.relative_to(base).with_suffix("")
            parts = [pkg, *rel.parts]
            if parts[-1] == "__init__":
                parts = parts[:-1]
            out[".".join(parts)] = p
    return out


def _canonical(name: str) -> str:
    # exporters/ is importable both as `exporters` and as `lod2energy.exporters`
    return "exporters" + name[len("lod2energy.exporters"):] if name.startswith("lod2energy.exporters") else name


def import_graph() -> dict[str, set[str]]:
    """Module -> the project modules it imports (anywhere in its body)."""
    mods = _modules()
    graph: dict[str, set[str]] = {m: set() for m in mods}
    for mod, path in mods.items():
        tree = ast.parse(path.read_text(encoding="utf-8"))
        is_pkg = path.name == "__init__.py"
        lazy = _lazy_entry(tree) if mod == "lod2energy" else set()
        for node in ast.walk(tree):
            if id(node) in lazy:
                continue
            targets = []
            if isinstance(node, ast.Import):
                targets = [a.name for a in node.names]
            elif isinstance(node, ast.ImportFrom):
                if node.level:
                    base = mod.split(".") if is_pkg else mod.split(".")[:-1]
                    base = base[:len(base) - (node.level - 1)]
                    src = ".".join(base + ([node.module] if node.module else []))
                else:
                    src = node.module or ""
                targets = [f"{src}.{a.name}" for a in node.names] + [src]
            for t in targets:
                t = _canonical(t)
                while t and t not in mods:
                    t = t.rpartition(".")[0]
                if t and t != mod and not mod.startswith(t + "."):
                    graph[mod].add(t)
                # importing a.b.c first runs the package a.b's __init__: a circle through a
                # package's eager imports is a circle too
                while "." in t:
                    t = t.rpartition(".")[0]
                    if t in mods and t != mod and not mod.startswith(t + "."):
                        graph[mod].add(t)
    return graph


def _lazy_entry(tree: ast.Module) -> set[int]:
    """The imports inside the package root's module ``__getattr__`` (PEP 562): the API's lazy
    entry, run when a caller asks for ``lod2energy.read``, never while a module is imported."""
    return {id(n) for fn in tree.body if isinstance(fn, ast.FunctionDef) and fn.name == "__getattr__"
            for n in ast.walk(fn) if isinstance(n, (ast.Import, ast.ImportFrom))}


def cycles(graph: dict[str, set[str]]) -> list[list[str]]:
    """Strongly connected components with more than one module (Tarjan)."""
    index, low, stack, on, out = {}, {}, [], set(), []
    counter = [0]

    def visit(v):
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on.add(v)
        for w in sorted(graph[v]):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on.discard(w)
                comp.append(w)
                if w == v:
                    break
            if len(comp) > 1:
                out.append(sorted(comp))

    for v in sorted(graph):
        if v not in index:
            visit(v)
    return out


def test_the_graph_sees_imports():
    g = import_graph()
    # the package whose module is imported counts too (its __init__ runs first)
    assert "lod2energy.repair" in g["lod2energy.prepare"]
    assert "lod2energy.geometry" in g["lod2energy.polymesh"]
    assert "lod2energy.polymesh" in g["lod2energy.repair.cleanup"]


def test_no_import_circle():
    found = cycles(import_graph())  # the writers' packages (exporters.*) included
    assert found == [], f"import circles: {found}"


def test_no_writer_imports_the_repair_package():
    # what a writer is given is made by a stage before it (lod2energy.energy), not by the writer
    g = import_graph()
    found = {m for m, deps in g.items() if m.startswith("exporters") and any(d.startswith("lod2energy.repair") for d in deps)}
    assert found == set(), sorted(found)


def test_core_geometry_imports_only_itself():
    """and the one caching module (which imports nothing of the project)"""
    g = import_graph()
    assert g["lod2energy.cache"] == set()
    for mod, deps in g.items():
        if mod.startswith("lod2energy.geometry"):
            assert all(d.startswith("lod2energy.geometry") or d == "lod2energy.cache" for d in deps), (mod, deps)


@pytest.mark.parametrize("rel", sorted(str(p.relative_to(ROOT)) for p in _modules().values()))
def test_module_size(rel):
    n = len((ROOT / rel).read_text(encoding="utf-8").splitlines())
    assert n <= EXEMPT_SIZE.get(rel, MAX_LINES), f"{rel}: {n} lines"


# --- one place for caches (lod2energy/cache.py) ----------------------------------------------

#: Module-level containers that change after import and are no caches, each with its reason.
MODULE_STATE = {
    "lod2energy.io._READERS": "the reader registry: each reader module registers itself on import",
    "exporters.registry._WRITERS": "the writer registry: each format package registers itself on import",
    "lod2energy.run.executor._CHILDREN": "run state: the budget process of each worker thread, to stop it",
}
_MUTABLE_CALLS = {"dict", "list", "set", "OrderedDict", "defaultdict", "deque", "Counter",
                  "WeakKeyDictionary", "WeakValueDictionary", "WeakSet"}
_MUTATORS = {"append", "add", "update", "setdefault", "pop", "popitem", "clear", "extend", "insert",
             "remove", "discard", "move_to_end", "appendleft", "__setitem__"}


def _is_mutable(value: ast.expr | None) -> bool:
    if isinstance(value, (ast.Dict, ast.List, ast.Set, ast.DictComp, ast.ListComp, ast.SetComp)):
        return True
    if isinstance(value, ast.Call):
        f = value.func
        return (f.id if isinstance(f, ast.Name) else f.attr if isinstance(f, ast.Attribute) else "") in _MUTABLE_CALLS
    return False


def _containers(tree: ast.Module) -> set[str]:
    """Names bound at module level to a mutable container."""
    out = set()
    for node in tree.body:
        if isinstance(node, ast.Assign) and _is_mutable(node.value):
            out |= {t.id for t in node.targets if isinstance(t, ast.Name)}
        elif isinstance(node, ast.AnnAssign) and isinstance(node.target, ast.Name) and _is_mutable(node.value):
            out.add(node.target.id)
    return out


def _changed_in_functions(tree: ast.Module, names: set[str]) -> set[str]:
    """Those of ``names`` that a function changes (item set or deleted, a mutating method called),
    and every name a function rebinds through ``global``: state that outlives the call."""
    out = set()
    for fn in ast.walk(tree):
        if not isinstance(fn, (ast.FunctionDef, ast.AsyncFunctionDef, ast.Lambda)):
            continue
        for node in ast.walk(fn):
            if isinstance(node, ast.Global):
                out |= set(node.names)
            elif isinstance(node, ast.Subscript) and isinstance(node.ctx, (ast.Store, ast.Del)) \
                    and isinstance(node.value, ast.Name) and node.value.id in names:
                out.add(node.value.id)
            elif isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute) \
                    and node.func.attr in _MUTATORS and isinstance(node.func.value, ast.Name) \
                    and node.func.value.id in names:
                out.add(node.func.value.id)
    return out


def _functools_caches(tree: ast.Module) -> list[int]:
    """Lines that use ``functools.lru_cache`` or ``functools.cache``."""
    lines = []
    for node in ast.walk(tree):
        if isinstance(node, ast.ImportFrom) and node.module == "functools" \
                and any(a.name in ("lru_cache", "cache") for a in node.names):
            lines.append(node.lineno)
        elif isinstance(node, ast.Attribute) and node.attr in ("lru_cache", "cache") \
                and isinstance(node.value, ast.Name) and node.value.id == "functools":
            lines.append(node.lineno)
    return lines


def module_caches() -> dict[str, list[str]]:
    """Module -> what it keeps outside :mod:`lod2energy.cache` (allowed state left out)."""
    found = {}
    for mod, path in _modules().items():
        if mod == "lod2energy.cache":
            continue
        tree = ast.parse(path.read_text(encoding="utf-8"))
        bad = [f"functools cache at line {n}" for n in _functools_caches(tree)]
        bad += sorted(name for name in _changed_in_functions(tree, _containers(tree))
                      if f"{mod}.{name}" not in MODULE_STATE)
        if bad:
            found[mod] = bad
    return found


def test_caches_live_in_the_one_caching_module():
    found = module_caches()
    assert found == {}, found


def test_the_cache_rule_sees_caches():
    tree = ast.parse("import functools\nfrom functools import lru_cache\n_SEEN = {}\n_ALL: list = []\n"
                     "TABLE = {k: k for k in 'ab'}\n_N = 0\n"
                     "@functools.cache\ndef f(x):\n    _SEEN[x] = 1\n    return TABLE[x]\n"
                     "def g():\n    global _N\n    _N += 1\n    _ALL.append(1)\n")
    assert len(_functools_caches(tree)) == 2
    assert _changed_in_functions(tree, _containers(tree)) == {"_SEEN", "_ALL", "_N"}


def test_allowed_module_state_exists():
    # a stale reason hides nothing: every allowed name is still a module-level container
    mods = _modules()
    for qual in MODULE_STATE:
        mod, _, name = qual.rpartition(".")
        assert name in _containers(ast.parse(mods[mod].read_text(encoding="utf-8"))), qual


# --- imports at the top -----------------------------------------------------------------------

#: The function-local imports left, by (module, imported package): each with its reason.
LOCAL_IMPORTS = {
    ("lod2energy.validate_files", "lod2energy"): "validate loads the export side only for a file or page that needs it",
    ("lod2energy.run.driver", "tqdm"): "a progress bar only when not quiet (0.1 s)",
    ("lod2energy.run.driver", "lod2energy"): "the writers a command declares, loaded when it runs (the CLI's head)",
    ("lod2energy", "lod2energy"): "the API's lazy entry (module __getattr__): import lod2energy stays light",
    # scipy costs about 0.4 s to import: loaded by the paths that need it (validation mostly does not)
    **{(m, "scipy"): "imported by the paths that need it" for m in (
        "lod2energy.geometry.cdt", "lod2energy.geometry.snap", "lod2energy.io.gml", "lod2energy.repair.alphashape",
        "lod2energy.repair.cleanup", "lod2energy.repair.footprint", "lod2energy.repair.metrics",
        "lod2energy.repair.parts",
        "lod2energy.repair.plausible", "lod2energy.viz.footprints", "lod2energy.viz.render")},
    ("lod2energy.options", "lod2energy"): "the writers' option classes load with their packages: on use",
    ("lod2energy.run.executor", "cloudpickle"): "optional (the dask extra)",
    ("lod2energy.run.executor", "dask"): "optional (the dask extra)",
    ("lod2energy.graph", "torch"): "optional (the pyg extra)",
    ("lod2energy.graph", "torch_geometric"): "optional (the pyg extra)",
    ("lod2energy.repair.alphashape", "pymeshlab"): "starts threads: loaded in the alpha-wrap child only",
    ("lod2energy.safe_write", "numpy"): "safe_write is on the CLI's head; numpy only for a report's arrays",
    ("lod2energy.site", "pyproj"): "a transformer only for outputs that need positions",
    ("lod2energy.crs", "pyproj"): "pyproj (0.1 s) only for a file that names a CRS, not for --help",
    ("lod2energy.run.blas_threads", "threadpoolctl"): "only when numpy is loaded already (the CLI's head)",
    ("lod2energy.viz.figures", "matplotlib"): "the report's pictures only",
    ("lod2energy.viz.render", "matplotlib"): "the report's pictures only",
    ("lod2energy.viz.report", "matplotlib"): "the report's pictures only",
    ("lod2energy.viz.report", "jinja2"): "the page's template: only when a page is written (0.1 s)",
    ("lod2energy.viz.report", "PIL"): "the plan picture of a large file only",
    ("exporters.cfd.options", "lod2energy"): "the CLI's parser builds CfdOptions: the region's geometry on use",
}


def local_imports() -> set[tuple[str, str]]:
    """(module, imported top-level package) of every import inside a function."""
    out = set()
    for mod, path in _modules().items():
        tree = ast.parse(path.read_text(encoding="utf-8"))
        for fn in ast.walk(tree):
            if isinstance(fn, (ast.FunctionDef, ast.AsyncFunctionDef)):
                for node in ast.walk(fn):
                    if isinstance(node, ast.Import):
                        out |= {(mod, a.name.split(".")[0]) for a in node.names}
                    elif isinstance(node, ast.ImportFrom):
                        out.add((mod, "lod2energy" if node.level else (node.module or "").split(".")[0]))
    return out


def test_imports_are_at_the_top():
    found = local_imports()
    assert found <= set(LOCAL_IMPORTS), sorted(found - set(LOCAL_IMPORTS))
    assert ("lod2energy.validate_files", "lod2energy") in found  # the control: the rule sees them


# --- docs/architecture.md names what is there ---------------------------------------------------

def architecture_paths() -> list[str]:
    """Paths named in backticks in docs/architecture.md (``lod2energy/...``, ``exporters/...``,
    and shorter ones such as ``validate/closed.py`` read inside those packages)."""
    text = (ROOT / "docs" / "architecture.md").read_text(encoding="utf-8")
    spans = re.findall(r"`([^`\s]+)`", text)
    return [s for s in spans if "/" in s and re.fullmatch(r"[\w.<>/-]+", s) and "<" not in s]


def test_architecture_names_only_paths_that_exist():
    paths = architecture_paths()
    assert "lod2energy/cache.py" in paths and "validate/closed.py" in paths  # the rule sees them
    missing = [p for p in paths
               if not any((base / p.rstrip("/")).exists() for base in (ROOT, ROOT / "lod2energy", ROOT / "exporters"))]
    assert missing == [], missing


def test_no_test_imports_the_writers_under_a_second_name():
    # exporters/ is installed as lod2energy.exporters; imported as the top-level ``exporters`` too
    # (the repository root is on sys.path under pytest) its writers would register themselves a
    # second time, and a test patching lod2energy.exporters.X would no longer reach the writer
    second = re.compile(r"^\s*(from exporters[. ]|import exporters\b)", re.M)
    found = [p.name for d in ("tests", "benchmarks") for p in sorted((ROOT / d).rglob("*.py"))
             if second.search(p.read_text(encoding="utf-8"))]
    assert not found, found


def test_every_package_is_installed():
    # pyproject lists the packages one by one: one left out installs in editable mode (tests) but
    # not with `pip install .` (the quick start), where importing it fails
    try:
        import tomllib
    except ImportError:  # Python 3.10
        import tomli as tomllib
    listed = set(tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))["tool"]["setuptools"]["packages"])
    found = {".".join(("lod2energy", *p.parent.relative_to(ROOT / "exporters").parts)).replace("lod2energy", "lod2energy.exporters", 1)
             if p.is_relative_to(ROOT / "exporters") else ".".join(p.parent.relative_to(ROOT).parts)
             for d in ("lod2energy", "exporters") for p in (ROOT / d).rglob("__init__.py")}
    assert found <= listed, sorted(found - listed)
