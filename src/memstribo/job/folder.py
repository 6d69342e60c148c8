"""What a results folder of ``memstribo run`` owns: the files its ``run.json`` lists, inside the folder.

A results folder is the user's folder too (``--out .`` is a checkout, ``--roughness`` may name a scan
inside it), so nothing is deleted on the strength of a file's name alone (issue #41):

* :func:`results_folder` refuses an empty folder name (``--out ''`` or ``run(out='')``), which would be
  the current folder;
* :func:`listed_path` resolves a path that ``run.json`` lists inside the folder, and refuses an absolute
  one, one with ``..`` and one whose symbolic links lead outside (a crafted ``run.json`` cannot make
  ``--resume`` delete elsewhere);
* :func:`owned_files` is every file the manifest lists as written by memstribo (its stages' files and
  its ``written`` list), each through :func:`listed_path`;
* :func:`clear_for_overwrite` (``--overwrite``) deletes exactly those, and refuses a folder that holds
  any other file or an input of the run.
"""

from __future__ import annotations

import json
import os
from collections.abc import Iterable, Mapping
from pathlib import Path, PurePosixPath, PureWindowsPath
from typing import Any

from memstribo.errors import InputError
from memstribo.units import printable

__all__ = ["results_folder", "listed_path", "owned_files", "written_files", "check_inputs_outside",
           "clear_for_overwrite", "MANIFEST_FILES"]

#: Files every run writes beside its stages' files (``run.json`` of a run before version 4 does not list
#: them in ``written``; they are owned by the manifest that sits beside them).
MANIFEST_FILES = ("run.json", "report.html", "parameters.toml", "references.txt")


def results_folder(out, option: str = "out") -> Path:
    """``out`` as a folder path, refused when empty (it would be the current folder).

    Parameters
    ----------
    out : str or os.PathLike
        The results folder the user gave.
    option : str
        How the user gave it, for the message: ``"--out"`` (the command line) or ``"out"`` (the API).

    Raises
    ------
    InputError
        ``out`` is empty or only blanks (``Path('')`` is ``.``: a run would write ``data/``, ``figures/``
        and ``report.html`` into the current folder without being asked to).
    """
    if out is None or (isinstance(out, str) and not out.strip()) or (not isinstance(out, str) and str(out) == ""):
        shown = f"{option} {out!r}" if option.startswith("-") else f"{option}={out!r}"
        example, here = ((f"{option} memstribo-results", f"{option} .") if option.startswith("-")
                         else (f"{option}='memstribo-results'", f"{option}='.'"))
        raise InputError(f"{shown}: an empty folder name is the current folder, and a run writes data/, figures/, "
                         f"report.html and run.json into its folder; give a folder name (e.g. {example}, or {here} "
                         "for the current folder on purpose).")
    return Path(out)


def written_files(folder: Path, stages: Iterable[str], with_map: bool) -> list[str]:
    """The files a run wrote that no stage lists, for ``run.json``'s ``written`` (relative to ``folder``).

    :data:`MANIFEST_FILES`, the tracebacks ``error_<stage>.txt`` of ``stages`` and, ``with_map``, the design
    map's ``map/map.*`` and ``map/points/*.json`` (written point by point, before the stage could list them):
    ``--overwrite`` deletes only what ``run.json`` lists.
    """
    stages = set(stages)
    names = list(MANIFEST_FILES)
    names += sorted(p.name for p in folder.glob("error_*.txt") if p.stem[len("error_"):] in stages)
    if with_map:
        names += [str(p.relative_to(folder)) for p in sorted((folder / "map").glob("map.*")) if p.is_file()]
        names += [str(p.relative_to(folder)) for p in sorted((folder / "map" / "points").glob("*.json"))
                  if p.is_file()]
    return names


def listed_path(folder: Path, relative: Any, where: str) -> Path:
    """The path ``relative`` that ``run.json`` lists, inside ``folder``; anything else refused.

    Parameters
    ----------
    folder : pathlib.Path
        The results folder.
    relative : str
        A path as ``run.json`` lists it, relative to the folder (``data/mesh.nc``).
    where : str
        What is being done, for the message (``"--resume"``, ``"--overwrite"``).

    Returns
    -------
    pathlib.Path
        ``folder / relative`` (not resolved: a symbolic link inside the folder stays the link).

    Raises
    ------
    InputError
        ``relative`` is not a non-empty string, is absolute (POSIX or Windows), holds ``..``, or leads
        outside the folder through a symbolic link.
    """
    manifest = folder / "run.json"
    if not isinstance(relative, str) or not relative.strip() or "\x00" in relative:
        why = "which is not a file name"
    elif PurePosixPath(relative).is_absolute() or PureWindowsPath(relative).is_absolute() \
            or PureWindowsPath(relative).drive or relative.startswith(("/", "\\")):
        why = "which is absolute"
    elif ".." in PurePosixPath(relative.replace("\\", "/")).parts:
        why = "which holds '..'"
    else:
        path = folder / relative
        try:
            inside = path.resolve().is_relative_to(folder.resolve())
        except (OSError, RuntimeError):  # a symbolic-link loop
            inside = False
        if inside:
            return path
        why = "which leads outside the folder through a symbolic link"
    raise InputError(f"{where}: {manifest} lists the file '{printable(relative, 300)}', {why}; a results folder owns only "
                     "files inside it, so nothing was deleted. Give a folder that memstribo wrote, or a new one.")


def owned_files(folder: Path, manifest: Mapping[str, Any], where: str) -> dict[str, Path]:
    """Every file ``manifest`` (a parsed ``run.json``) lists as written, by its relative path.

    The stages' ``files``, the manifest's ``written`` list (the run's other files: ``report.html``,
    ``parameters.toml``, error tracebacks, the design map's points) and :data:`MANIFEST_FILES`; each
    checked by :func:`listed_path`. Raises :class:`InputError` on a path outside the folder or a
    manifest of the wrong shape.
    """
    listed: list[Any] = list(MANIFEST_FILES)
    try:
        for stage in manifest.get("stages", []):
            listed.extend(stage.get("files", []))
            listed.append(f"error_{stage['name']}.txt")
        listed.extend(manifest.get("written", []))
        for figure in manifest.get("figures", []):  # the report links figures/<stem>.png and .svg
            listed.extend(f"figures/{figure['stem']}.{suffix}" for suffix in ("png", "svg"))
    except (AttributeError, KeyError, TypeError) as exc:
        raise InputError(f"{where}: {folder / 'run.json'} is not a run.json of memstribo ({type(exc).__name__}: "
                         f"{printable(exc)}); nothing was deleted. Give a folder that memstribo wrote, or a new "
                         "one.") from None
    owned: dict[str, Path] = {}
    for relative in listed:
        path = listed_path(folder, relative, where)
        owned[os.path.normpath(relative)] = path
    return owned


def check_inputs_outside(folder: Path, inputs: Iterable[Any], where: str, files: Iterable[Path] | None = None) -> None:
    """Refuse when an input file of the run lies inside ``folder`` (or is one of ``files``).

    Parameters
    ----------
    folder : pathlib.Path
        The results folder.
    inputs : iterable of str or Path
        The run's input files (``--roughness`` and ``[run] roughness_files``, the config file, ``[run] map``).
    where : str
        What would delete it, for the message (``"--overwrite"``, ``"--resume"``).
    files : iterable of Path, optional
        Only these files of the folder are at stake (``--resume`` deletes only a failed stage's files);
        None: the whole folder.
    """
    base = folder.resolve()
    at_stake = None if files is None else {Path(f).resolve() for f in files}
    for item in inputs:
        if item is None or str(item) == "":
            continue
        path = Path(item).expanduser().resolve()
        hit = path.is_relative_to(base) if at_stake is None else path in at_stake
        if hit:
            raise InputError(f"{where}: the input file {printable(item, 300)} lies in the results folder {folder}, and "
                             f"{where} would delete it; nothing was deleted. Give another --out folder (a new one), "
                             "or move the input out of it.")


def _all_files(folder: Path) -> list[str]:
    """Every file and symbolic link under ``folder`` (links not followed), relative, normalised."""
    found = []
    for root, dirs, files in os.walk(folder, followlinks=False):
        for name in files + [d for d in dirs if os.path.islink(os.path.join(root, d))]:
            found.append(os.path.normpath(os.path.relpath(os.path.join(root, name), folder)))
    return sorted(found)


def clear_for_overwrite(folder: Path, inputs: Iterable[Any] = (), option: str = "--out") -> list[str]:
    """``--overwrite``: delete the files the folder's ``run.json`` lists as written by memstribo, nothing else.

    Parameters
    ----------
    folder : pathlib.Path
        An existing, non-empty results folder.
    inputs : iterable of str or Path
        The new run's input files: none may lie in the folder.
    option : str
        The option that named the folder, for the messages.

    Returns
    -------
    list of str
        The files deleted (relative to the folder).

    Raises
    ------
    InputError
        (nothing deleted) an input file of the run lies in the folder; the folder holds no readable
        ``run.json``; the manifest lists a path outside the folder; or the folder holds a file the
        manifest does not list (a foreign file: the user's, not memstribo's).
    """
    where = "--overwrite"
    check_inputs_outside(folder, inputs, where)
    manifest_path = folder / "run.json"
    if not manifest_path.is_file():
        raise InputError(f"{option} {folder}: --overwrite deletes only the files a run's run.json lists, but the folder "
                         "holds no run.json (it is not a results folder of memstribo, or its run was killed before "
                         "its first stage ended); nothing was deleted. Give an empty or new folder, or empty this "
                         "one by hand.")
    try:
        manifest = json.loads(manifest_path.read_text(encoding="utf-8"))
        if not isinstance(manifest, dict):
            raise ValueError("not a JSON object")
    except (OSError, ValueError) as exc:
        raise InputError(f"{option} {folder}: its run.json cannot be read ({printable(exc)}), so what memstribo wrote "
                         "there is unknown; nothing was deleted. Give an empty or new folder.") from None
    owned = owned_files(folder, manifest, where)
    foreign = [name for name in _all_files(folder) if name not in owned]
    if foreign:
        shown = ", ".join(printable(name) for name in foreign[:5]) + (f" and {len(foreign) - 5} more"
                                                                      if len(foreign) > 5 else "")
        raise InputError(f"{option} {folder}: --overwrite deletes only the files its run.json lists as written by "
                         f"memstribo, but the folder also holds {shown}; nothing was deleted. Give an empty or new "
                         "folder, or move those files out.")
    deleted = []
    parents = set()
    for name, path in owned.items():
        if path.is_file() or path.is_symlink():
            path.unlink()
            deleted.append(name)
            parents.update(p for p in path.relative_to(folder).parents if str(p) != ".")
    for parent in sorted(parents, key=lambda p: len(p.parts), reverse=True):  # deepest first; only if emptied
        directory = folder / parent
        if directory.is_dir() and not directory.is_symlink() and not any(directory.iterdir()):
            directory.rmdir()
    return deleted
