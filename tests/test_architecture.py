"""The package's import graph (#11 item 6): built from every import statement, including those inside
functions; no cycles, the command line imported only by itself, no module loaded by name."""

import ast
from pathlib import Path

import pytest

SRC = Path(__file__).resolve().parent.parent / "src" / "memstribo"


def _module_name(path: Path) -> str:
    parts = list(path.relative_to(SRC.parent).with_suffix("").parts)
    if parts[-1] == "__init__":
        parts = parts[:-1]
    return ".".join(parts)


def _resolve(module: str, is_package: bool, level: int, target: str | None) -> str:
    base = module.split(".") if is_package else module.split(".")[:-1]
    if level:
        base = base[: len(base) - (level - 1)]
        return ".".join(base + ([target] if target else []))
    return target or ""


def import_graph() -> dict[str, set[str]]:
    """memstribo module -> the memstribo modules it imports (anywhere in the file)."""
    modules = {_module_name(p): p for p in SRC.rglob("*.py")}
    graph = {name: set() for name in modules}
    for name, path in modules.items():
        is_package = path.name == "__init__.py"
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            targets = []
            if isinstance(node, ast.Import):
                targets = [alias.name for alias in node.names]
            elif isinstance(node, ast.ImportFrom):
                base = _resolve(name, is_package, node.level, node.module)
                targets = [base] + [f"{base}.{alias.name}" for alias in node.names]
            for target in targets:
                if target.startswith("memstribo"):
                    # an imported name that is a module counts as that module, else its package
                    while target and target not in modules:
                        target = target.rpartition(".")[0]
                    if target and target != name:
                        graph[name].add(target)
    return graph


def _cycles(graph):
    seen, stack, on_stack, found = set(), [], set(), []

    def visit(node):
        seen.add(node)
        stack.append(node)
        on_stack.add(node)
        for nxt in sorted(graph[node]):
            if nxt in on_stack:
                found.append(stack[stack.index(nxt):] + [nxt])
            elif nxt not in seen:
                visit(nxt)
        stack.pop()
        on_stack.discard(nxt if False else node)

    for node in sorted(graph):
        if node not in seen:
            visit(node)
    return found


# a package's __init__ importing its own submodules, and a submodule importing a sibling through the package,
# are not layering cycles: the edges that matter run between different top-level parts
def _between_parts(graph):
    out = {}
    for module, targets in graph.items():
        out[module] = {t for t in targets if not (module == "memstribo" or t == "memstribo")}
    return out


def test_no_import_cycles():
    cycles = _cycles(_between_parts(import_graph()))
    assert not cycles, "import cycles: " + "; ".join(" -> ".join(c) for c in cycles[:5])


def test_nothing_below_the_command_line_imports_it():
    graph = import_graph()
    offenders = {m: sorted(t for t in targets if t.startswith("memstribo.cli"))
                 for m, targets in graph.items() if not m.startswith("memstribo.cli")}
    assert not {m: t for m, t in offenders.items() if t}


def test_no_module_is_loaded_by_name():
    offenders = []
    for path in SRC.rglob("*.py"):
        if path.parent.name == "cli" and path.name == "main.py":
            continue  # the CLI discovers its subcommand modules (one per file in cli/)
        text = path.read_text(encoding="utf-8")
        if "import_module(" in text or "__import__(" in text:
            offenders.append(str(path.relative_to(SRC)))
    assert not offenders, offenders


@pytest.mark.parametrize("module", ["memstribo", "memstribo.cli.main"])
def test_package_import_is_light(module):
    import subprocess
    import sys

    code = (f"import sys, {module}; heavy = [m for m in ('matplotlib', 'SurfaceTopography', 'dask', 'distributed', "
            f"'xarray', 'scipy', 'numba') if m in sys.modules]; print(','.join(heavy))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout.strip()
    assert out == "", f"import {module} loads {out}"


#: The layers of the tree (docs/architecture.md), lowest first; a module may import only from its own layer or
#: from layers below it. The foundation (errors, units, checks, references, output, parameters) serves all.
LAYERS = [
    ("foundation", ("memstribo.errors", "memstribo.units", "memstribo.checks", "memstribo.references", "memstribo.quantities", "memstribo.heap",
                    "memstribo.output", "memstribo.parameters")),
    ("surfaces", ("memstribo.surfaces",)),
    ("materials", ("memstribo.materials",)),
    ("physics", ("memstribo.physics",)),
    ("simulations", ("memstribo.simulations", "memstribo.uncertainty")),
    ("validation", ("memstribo.validation", "memstribo.laboratory")),
    ("job", ("memstribo.job",)),
    ("api", ("memstribo.api",)),
    ("cli", ("memstribo.cli",)),
]


def layer_of(module: str) -> int:
    for rank, (_, prefixes) in enumerate(LAYERS):
        if any(module == p or module.startswith(p + ".") for p in prefixes):
            return rank
    raise AssertionError(f"{module} belongs to no layer: add it to LAYERS and to docs/architecture.md")


def test_every_module_sits_in_a_layer_and_imports_point_down():
    graph = import_graph()
    upward = []
    for module, targets in graph.items():
        if module == "memstribo":
            continue  # the package's __init__: the version, the errors, and the public API on first use
        rank = layer_of(module)
        upward += [f"{module} ({LAYERS[rank][0]}) imports {t} ({LAYERS[layer_of(t)][0]})"
                   for t in sorted(targets) if t != "memstribo" and layer_of(t) > rank]
    assert not upward, "imports pointing up the layers:\n" + "\n".join(upward)


def test_the_layers_are_folders_a_newcomer_sees():
    for name, prefixes in LAYERS[1:-1]:
        for prefix in prefixes:
            path = SRC.parent / prefix.replace(".", "/")
            assert path.is_dir() or path.with_suffix(".py").is_file(), prefix


# ----------------------------------------------------------------------------- rooms a newcomer can live in (#24)

#: Longest module [lines] and function [lines, decorators and docstring included] anywhere in src/memstribo.
MAX_MODULE_LINES = 900
MAX_FUNCTION_LINES = 100
#: Modules allowed past MAX_MODULE_LINES for now, each with why.
LONG_MODULES: set[str] = set()
#: Functions allowed past MAX_FUNCTION_LINES, by "module path:function name": the CLI's argument tables, which
#: are a flat list of options (none at present).
LONG_FUNCTIONS: set[str] = set()


def _functions(tree):
    for node in ast.walk(tree):
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
            start = min([node.lineno] + [d.lineno for d in node.decorator_list])
            yield node.name, node.end_lineno - start + 1


def test_no_module_is_over_900_lines():
    long = {str(p.relative_to(SRC)): n for p in SRC.rglob("*.py")
            if (n := len(p.read_text(encoding="utf-8").splitlines())) > MAX_MODULE_LINES}
    assert not {m: n for m, n in long.items() if m not in LONG_MODULES}, \
        f"modules over {MAX_MODULE_LINES} lines (split them where the split shows the physics): {long}"


def test_no_function_is_over_100_lines():
    long = []
    for path in SRC.rglob("*.py"):
        module = str(path.relative_to(SRC))
        for name, length in _functions(ast.parse(path.read_text(encoding="utf-8"))):
            if length > MAX_FUNCTION_LINES and f"{module}:{name}" not in LONG_FUNCTIONS:
                long.append(f"{module}:{name} ({length} lines)")
    assert not long, f"functions over {MAX_FUNCTION_LINES} lines: " + ", ".join(sorted(long))


@pytest.mark.parametrize("package, modules", [
    ("physics/contact", ("settings", "halfplane", "inputs", "line", "dense", "cohesive", "solve")),
    ("simulations/mesh", ("setup", "contacts", "interface", "steps", "verdict", "record", "cycle", "ensemble",
                          "sweeps")),
])
def test_the_two_big_rooms_are_packages_whose_modules_say_what_they_are(package, modules):
    folder = SRC / package
    assert (folder / "__init__.py").is_file() and not folder.with_suffix(".py").exists()
    for name in modules:
        doc = ast.get_docstring(ast.parse((folder / f"{name}.py").read_text(encoding="utf-8")))
        assert doc and doc.split("\n\n")[0].strip(), f"{package}/{name}.py opens with no line on what it is"
    # within the packages a function is short enough to read on one screen
    for path in folder.glob("*.py"):
        long = [f"{n} ({k})" for n, k in _functions(ast.parse(path.read_text(encoding="utf-8"))) if k > 100]
        assert not long, f"{path.name}: {long}"


def test_every_solver_setting_says_what_it_trades_and_which_benchmark_set_it():
    """Every field of SolverSettings has a docstring naming its unit (or kind) and a script in bench/."""
    import dataclasses

    from memstribo.physics.contact import SolverSettings

    tree = ast.parse((SRC / "physics/contact/settings.py").read_text(encoding="utf-8"))
    body = next(n for n in tree.body if isinstance(n, ast.ClassDef) and n.name == "SolverSettings").body
    docs = {}
    for node, following in zip(body, body[1:]):
        if isinstance(node, ast.AnnAssign) and isinstance(following, ast.Expr) and isinstance(following.value,
                                                                                              ast.Constant):
            docs[node.target.id] = following.value.value
    fields = [f.name for f in dataclasses.fields(SolverSettings)]
    assert fields and set(docs) == set(fields)
    bench = {p.name for p in (SRC.parent.parent / "bench").glob("bench_*.py")}
    for name, doc in docs.items():
        named = [b for b in bench if b in doc]
        assert named, f"SolverSettings.{name}: no bench/ script named"
    with pytest.raises(dataclasses.FrozenInstanceError):
        SolverSettings().max_outer = 1


def test_the_solvers_constants_live_only_in_the_settings():
    """No module of the contact package keeps a module-level tuning constant of its own."""
    import re

    for path in (SRC / "physics/contact").glob("*.py"):
        if path.name == "settings.py":
            continue
        tree = ast.parse(path.read_text(encoding="utf-8"))
        constants = [t.id for node in tree.body if isinstance(node, ast.Assign) for t in node.targets
                     if isinstance(t, ast.Name) and re.fullmatch(r"_?[A-Z][A-Z0-9_]*", t.id)]
        assert not constants, f"{path.name}: {constants}"


def test_every_data_file_of_the_package_is_installed():
    """A wheel carries only the package data pyproject.toml names: every non-Python file under src/memstribo must
    match one of its patterns (laboratory/materials.toml was missed once: a non-editable install lost it)."""
    import fnmatch
    import tomllib

    root = Path(__file__).resolve().parent.parent
    patterns = tomllib.loads((root / "pyproject.toml").read_text())["tool"]["setuptools"]["package-data"]["memstribo"]
    package = root / "src" / "memstribo"
    data = [p.relative_to(package).as_posix() for p in package.rglob("*")
            if p.is_file() and p.suffix not in (".py", ".pyc") and "__pycache__" not in p.parts]
    assert data
    missing = [name for name in data if not any(fnmatch.fnmatch(name, pattern) for pattern in patterns)]
    assert not missing, f"not in [tool.setuptools.package-data]: {missing}"
