"""Sphinx configuration of memstribo's documentation, one site: the guides (the Markdown pages of
``docs/``, through myst-parser), the API reference from the docstrings (``docs/api/``, numpydoc style
through napoleon) and the worked example notebook (``docs/examples/`` links to
``examples/worked_example.ipynb``; myst-nb executes it during the build, as it is committed without
outputs).

Build from the repository root::

    python -m sphinx -W --keep-going -b html docs docs/_build/html

``tests/test_docs_build.py`` runs the same build with warnings as errors.
"""

from __future__ import annotations

import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "src"))  # a source checkout that is not installed still builds

from memstribo import __version__  # noqa: E402

project = "memstribo"
author = "memstribo developers"
copyright = "2026, memstribo developers (MIT licence)"
version = release = __version__

root_doc = "index"
extensions = [
    "myst_nb",  # myst-parser's Markdown, and notebooks
    "sphinx.ext.autodoc",
    "sphinx.ext.autosummary",
    "sphinx.ext.extlinks",
    "sphinx.ext.mathjax",
    "sphinx.ext.napoleon",
    "sphinx.ext.viewcode",
]
exclude_patterns = ["_build", "**/.ipynb_checkpoints", "jupyter_execute"]

# the worked example: executed during the build (it is committed without outputs; about 20-40 s),
# a failing cell fails the build
nb_execution_mode = "auto"
nb_execution_timeout = 180
nb_execution_raise_on_error = True
nb_execution_show_tb = True
nb_execution_in_temp = False  # the notebook finds data/afm/ from its folder, like a reader's Jupyter

# numpydoc-style docstrings ("Parameters\n----------")
napoleon_google_docstring = False
napoleon_numpy_docstring = True
napoleon_use_rtype = False
napoleon_use_param = False  # types stay text: "float, optional" links nothing, so no ambiguous cross-references
napoleon_use_ivar = True
napoleon_preprocess_types = False

autodoc_default_options = {"members": True, "undoc-members": False, "show-inheritance": False,
                           "member-order": "bysource"}
autodoc_typehints = "description"
autodoc_typehints_format = "short"
autosummary_generate = False
# heavy optional imports are mocked nowhere: every dependency is installed with memstribo

# Markdown pages: GitHub-style heading anchors for links like [x](model.md#3-adhesion)
myst_heading_anchors = 3
myst_enable_extensions = ["dollarmath"]

html_theme = "alabaster"
html_title = f"memstribo {release}"
html_static_path: list[str] = []

# the docstrings cite papers as :doi:`10.xxxx/...`
extlinks = {"doi": ("https://doi.org/%s", "doi:%s")}

# --- docstrings as written in memstribo, made into valid reStructuredText ----------------------
import re  # noqa: E402

_FOOTNOTE_REF = re.compile(r"\[(\d+)\]_")
_FOOTNOTE_DEF = re.compile(r"^(\s*)\.\. \[(\d+)\](\s|$)")
_BARS = re.compile(r"(?<![\\|])\|(?=\S)([^|`]*?\S)\|(?![_|])")

#: Module docstrings written as plain text (aligned columns) rather than reStructuredText,
#: shown as preformatted text: memstribo.job.chain (its stage list; owned elsewhere, see the report).
PLAIN_TEXT_DOCSTRINGS = {"memstribo.job.chain"}


def _escape_bars(line: str) -> str:
    """|x| (absolute values in plain-text formulas) outside inline literals and roles, not as substitutions."""
    parts = re.split(r"(`[^`]*`)", line)
    return "".join(part if part.startswith("`") else _BARS.sub(r"\\|\1\\|", part) for part in parts)


def _label(name: str) -> str:
    return re.sub(r"[^A-Za-z0-9]+", "-", name).strip("-")


def _page_module(name: str, what: str) -> str:
    """The module whose page documents ``name`` (the longest imported prefix)."""
    if what == "module":
        return name
    parts = name.split(".")
    for end in range(len(parts) - 1, 0, -1):
        if ".".join(parts[:end]) in sys.modules:
            return ".".join(parts[:end])
    return name


def _defined(lines) -> set[str]:
    return {m.group(2) for m in (_FOOTNOTE_DEF.match(line) for line in lines) if m}


def _cited_in_module(module: str) -> set[str]:
    import inspect

    try:
        return set(_FOOTNOTE_REF.findall(inspect.getsource(sys.modules[module])))
    except (KeyError, OSError, TypeError):
        return set()


def _footnotes(name: str, what: str, obj, lines: list[str]) -> list[str]:
    """numpydoc-style references made valid on a page with many docstrings.

    A module docstring's ``.. [1]`` list serves the whole module (functions cite it as ``[1]_``);
    a function may have its own list. Labels become unique per module or per object (several
    docstrings of one page use ``[1]``); references never cited become plain list entries; a
    citation whose list is not on this page (a function re-exported from another module) is
    shown as plain ``[1]``.
    """
    module = _page_module(name, what)
    module_label = _label(module)
    module_defs = _defined((sys.modules[module].__doc__ or "").splitlines()) if module in sys.modules else set()
    own_module = what == "module" or getattr(obj, "__module__", module) == module
    if what == "module":
        local, local_label, cited = set(), module_label, _cited_in_module(module)
    else:
        local, local_label = _defined(lines), _label(name)
        cited = set(_FOOTNOTE_REF.findall("\n".join(lines)))

    def ref(match):
        n = match.group(1)
        if what == "module" and n in module_defs or n in local:
            return f"[#{local_label}-{n}]_"
        if n in module_defs and own_module:
            return f"[#{module_label}-{n}]_"
        return f"[{n}]"

    out: list[str] = []
    continuation = None  # indent of a definition being turned into a paragraph
    for line in lines:
        if continuation is not None:
            if line.strip() and len(line) - len(line.lstrip()) > continuation:
                out.append(" " * continuation + line.lstrip())
                continue
            continuation = None
        match = _FOOTNOTE_DEF.match(line)
        if match and match.group(2) not in cited:
            indent = match.group(1)
            if out and out[-1].strip():
                out.append("")
            out.append(f"{indent}[{match.group(2)}] " + line[match.end():].lstrip())
            continuation = len(indent)
            continue
        if match:
            rest = line[match.end() - len(match.group(3)):]
            line = f"{match.group(1)}.. [#{local_label}-{match.group(2)}]" + rest
        out.append(_FOOTNOTE_REF.sub(ref, line))
    return out


def _process_docstring(app, what, name, obj, options, lines):
    if what == "module" and name in PLAIN_TEXT_DOCSTRINGS:
        lines[:] = ["::", ""] + ["    " + line for line in lines]
        return
    lines[:] = [_escape_bars(line) for line in _footnotes(name, what, obj, lines)]


def setup(app):
    app.connect("autodoc-process-docstring", _process_docstring)
