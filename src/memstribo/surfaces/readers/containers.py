"""contact.engineering ``.zip`` containers: pick the member, read it with its own calibration."""

from __future__ import annotations

import io
import re
import zipfile
from pathlib import Path


from memstribo.errors import DataFileError
from memstribo.units import printable
from memstribo.surfaces.readers._common import SurfaceMap, _TEXT
from memstribo.surfaces.readers.instruments import _NotRead, _st_open, _st_topography
from memstribo.surfaces.readers.text import _read_text

def _container_meta(archive):
    try:
        import yaml
    except ImportError:  # pragma: no cover - SurfaceTopography depends on PyYAML
        return {}

    class Loader(yaml.SafeLoader):
        pass

    Loader.add_constructor("tag:yaml.org,2002:python/tuple", lambda loader, node: tuple(loader.construct_sequence(node)))
    try:
        meta = yaml.load(archive.read("meta.yml"), Loader=Loader)
    except Exception:
        return {}
    units = {}
    for surface in (meta or {}).get("surfaces", []):
        for topo in surface.get("topographies", []):
            original = (topo.get("datafile") or {}).get("original")
            if original:
                units[original] = topo
    return units


def _is_afm_member(member):
    return re.search(r"\.(\d{3}|di|spm|ibw|tiff?|gwy|x3p|nc|opdx|sur|plu|mi|nid|datx)$", member, re.IGNORECASE)


def _read_container(path, name, channel, unit, physical_size=None):
    try:
        archive = zipfile.ZipFile(path)
    except (zipfile.BadZipFile, OSError, EOFError, ValueError) as exc:
        raise DataFileError(f"{path}: not a readable zip container ({printable(exc, 100)}).") from None
    with archive:
        members = [m for m in archive.namelist() if not m.endswith("/") and not m.lower().startswith("license")
                   and m != "meta.yml"]
        if not members:
            raise DataFileError(f"{path}: the zip holds no measurement files.")
        meta = _container_meta(archive)
        member_text, _, channel_text = (channel or "").partition("::")
        shown = [printable(m, 60) for m in members[:10]] + (["..."] if len(members) > 10 else [])
        if member_text:
            chosen = [m for m in members if m == member_text] or [m for m in members if member_text.lower() in m.lower()]
            if len(chosen) != 1:
                what = "matches several members" if chosen else "matches no member"
                raise DataFileError(f"{path}: channel '{printable(channel, 60)}' {what}. Members: {', '.join(shown)} "
                                    "(give a member name or a unique part of it; add '::CHANNEL' for a channel "
                                    "inside it).")
            member = chosen[0]
        else:
            afm = [m for m in members if _is_afm_member(m)]
            member = (afm or members)[0]
        if archive.getinfo(member).file_size > _MEMBER_MAX_BYTES:
            raise DataFileError(f"{path}: member '{printable(member, 60)}' unpacks to "
                                f"{archive.getinfo(member).file_size:,} bytes; memstribo reads members of at most "
                                f"{_MEMBER_MAX_BYTES:,}.")
        try:
            data = archive.read(member)
        except (zipfile.BadZipFile, OSError, EOFError, ValueError, NotImplementedError, RuntimeError) as exc:
            raise DataFileError(f"{path}: member '{printable(member, 60)}' cannot be unpacked "
                                f"({printable(exc, 100)}); the zip is damaged.") from None
    member_path = f"{path}::{printable(member, 80)}"
    member_name = f"{Path(path).name}/{printable(member, 80)}"
    declared = (meta.get(member) or {}).get("unit")
    declared = declared if isinstance(declared, str) else None
    if member.lower().endswith(_TEXT):
        profile = _read_text(data, member_path, member_name, unit, declared_unit=declared,
                             physical_size=physical_size)
        extra = f"; unit {declared} from meta.yml" if declared else ""
        if isinstance(profile, SurfaceMap):
            return profile
        return profile.replace(source=profile.source + extra)
    try:
        reader = _st_open(io.BytesIO(data), member_path, Path(member).suffix.lower())
    except _NotRead as exc:
        raise DataFileError(f"{member_path}: SurfaceTopography cannot read this member ({exc}).") from None
    result = _st_topography(reader, member_path, member_name, channel_text or None, unit,
                            physical_size=physical_size)
    note = "; the member's own Z calibration (meta.yml's height_scale is not applied again)"
    if isinstance(result, SurfaceMap):
        return SurfaceMap(heights=result.heights, dx=result.dx, dy=result.dy, name=result.name,
                          source=result.source + note, channel=f"{member}::{result.channel}")
    return result.replace(source=result.source + note)


#: largest zip member memstribo unpacks (a crafted zip can unpack to far more than it holds)
_MEMBER_MAX_BYTES = 2 * 2**30

