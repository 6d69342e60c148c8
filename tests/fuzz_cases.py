"""Bad inputs for the command line, by kind: what tests/test_fuzz_inputs.py runs (issues #14, #15).

Each case writes what it needs into a folder and gives the ``memstribo`` arguments, a text the
message must contain (the file or parameter it names) and what must happen: ``"error"`` (exit
status 2 and one short, clean message) or ``"same"`` (read correctly: the same JSON as the
plain file, e.g. a UTF-8 BOM). ``python tests/fuzz_cases.py`` runs them all and prints the
table of docs/hardening.md.
"""

from __future__ import annotations

import math
import random
import re
from dataclasses import dataclass
from pathlib import Path
from typing import Callable

REPO = Path(__file__).resolve().parent.parent
AFM = REPO / "data" / "afm"
INSTRUMENT_FILES = sorted(p.name for p in AFM.iterdir() if p.name != "README.md")

#: extensions given random bytes and zero bytes
EXTENSIONS = (".txt", ".csv", ".dat", ".asc", ".xyz", ".di", ".001", ".spm", ".tif", ".tiff", ".ibw", ".opdx",
              ".gwy", ".x3p", ".nc", ".sur", ".plu", ".npy", ".zip", ".mi", ".nid", ".datx", ".h5", ".mat",
              ".sdf", ".stp", ".vk4", ".frt", ".zon", ".nms")

MAX_LINES, MAX_CHARS = 5, 600


@dataclass(frozen=True)
class Case:
    kind: str
    name: str
    build: Callable[[Path], tuple[list[str], str]]   # folder -> (argv, text the message must name)
    expect: str = "error"                            # "error" or "same" (argv of the reference in build's 3rd item)
    reference: Callable[[Path], list[str]] | None = None

    @property
    def id(self) -> str:
        return f"{self.kind}:{self.name}"


# --- measured files -----------------------------------------------------------------------------------

def _truncated(name: str, fraction: float):
    def build(folder: Path):
        data = (AFM / name).read_bytes()
        path = folder / f"cut{int(fraction * 100)}_{name}"
        path.write_bytes(data[: int(len(data) * fraction)])
        return ["roughness", str(path), "--json"], path.name
    return build


def _random_bytes(suffix: str, seed: int):
    def build(folder: Path):
        rng = random.Random(seed)
        path = folder / f"random{seed}{suffix}"
        path.write_bytes(bytes(rng.randrange(256) for _ in range(3000)))
        return ["roughness", str(path), "--json"], path.name
    return build


def _zero_bytes(suffix: str):
    def build(folder: Path):
        path = folder / f"zero{suffix}"
        path.write_bytes(b"")
        return ["roughness", str(path), "--json"], path.name
    return build


def _profile_rows(n=64):
    return [(i * 1e-8, math.sin(i / 3.0) * 1e-9) for i in range(n)]


def _plain_text(rows, sep=" "):
    return "".join(f"{x!r}{sep}{z!r}\n" for x, z in rows)


def _text_file(suffix: str, body: Callable[[], bytes], tag: str):
    def build(folder: Path):
        path = folder / f"{tag}{suffix}"
        path.write_bytes(body())
        return ["roughness", str(path), "--json"], path.name
    return build


def _reference(suffix: str):
    def build(folder: Path):
        path = folder / f"reference{suffix}"
        sep = "," if suffix == ".csv" else " "
        path.write_text(_plain_text(_profile_rows(), sep))
        return ["roughness", str(path), "--json"]
    return build


def _rows_with(change):
    rows = _profile_rows()
    change(rows)
    return rows


_TEXT_ERRORS = {
    "nan": lambda: _plain_text(_rows_with(lambda r: r.__setitem__(5, (r[5][0], float("nan"))))).encode(),
    "inf": lambda: _plain_text(_rows_with(lambda r: r.__setitem__(5, (r[5][0], float("inf"))))).encode(),
    "minus_inf_x": lambda: _plain_text(_rows_with(lambda r: r.__setitem__(5, (float("-inf"), r[5][1])))).encode(),
    "non_monotonic": lambda: _plain_text(_rows_with(lambda r: r.__setitem__(5, (r[3][0], r[5][1])))).encode(),
    "duplicate_x": lambda: _plain_text(_rows_with(lambda r: r.__setitem__(5, (r[4][0], r[5][1])))).encode(),
    "reversed": lambda: _plain_text(list(reversed(_profile_rows()))).encode(),
    "one_point": lambda: _plain_text(_profile_rows(1)).encode(),
    "two_points": lambda: _plain_text(_profile_rows(2)).encode(),
    "huge_heights": lambda: _plain_text([(x, z * 1e300) for x, z in _profile_rows()]).encode(),
    "huge_x": lambda: _plain_text([(x * 1e300, z) for x, z in _profile_rows()]).encode(),
    "tiny_x_step": lambda: _plain_text([(x * 1e-12, z) for x, z in _profile_rows()]).encode(),
    "pipe_delimiter": lambda: _plain_text(_profile_rows(), "|").encode(),
    "colon_delimiter": lambda: _plain_text(_profile_rows(), ":").encode(),
    "slash_delimiter": lambda: _plain_text(_profile_rows(), "/").encode(),
    "decimal_comma": lambda: _plain_text(_profile_rows(), ";").replace(".", ",").encode(),
    "ragged_columns": lambda: (_plain_text(_profile_rows()) + "1.0\n").encode(),
    "words": lambda: b"hello world\nthis is not data\n",
    "only_comments": lambda: b"# x z\n# nothing here\n",
    "header_not_length": lambda: ("x (um), z (V)\n" + _plain_text(_profile_rows())).encode(),
    "header_one_unit": lambda: ("x [um], z\n" + _plain_text(_profile_rows())).encode(),
    "escape_sequences": lambda: b"\x1b[2J\x1b]0;pwned\x07 1 2\n" + _plain_text(_profile_rows()).encode(),
    "nul_bytes": lambda: _plain_text(_profile_rows()).encode().replace(b"\n", b"\x00\n"),
    "utf16_odd_length": lambda: "0 1\n".encode("utf-16") + b"\x00",
    "all_zero_heights": lambda: _plain_text([(x, 0.0) for x, _ in _profile_rows()]).encode(),
    "single_column_no_size": lambda: "".join(f"{z!r}\n" for _, z in _profile_rows()).encode(),
}

_TEXT_SAME = {
    "utf8_bom": lambda sep: b"\xef\xbb\xbf" + _plain_text(_profile_rows(), sep).encode(),
    "utf16": lambda sep: _plain_text(_profile_rows(), sep).encode("utf-16"),
    "cr_only": lambda sep: _plain_text(_profile_rows(), sep).replace("\n", "\r").encode(),
    "crlf": lambda sep: _plain_text(_profile_rows(), sep).replace("\n", "\r\n").encode(),
    "latin1_comment": lambda sep: "# mesure \xe9chantillon\n".encode("latin-1") + _plain_text(_profile_rows(), sep).encode(),
}


# --- config files --------------------------------------------------------------------------------------

_CONFIGS = {
    "syntax:missing_value": ("syntax", "normal_load = \n"),
    "syntax:unclosed_table": ("syntax", "[parameters\nnormal_load = 1e-5\n"),
    "syntax:duplicate_key": ("syntax", "normal_load = 1e-5\nnormal_load = 2e-5\n"),
    "syntax:unterminated_string": ("syntax", 'normal_load = "25 uN\n'),
    "syntax:bad_escape": ("syntax", 'normal_load = "25 \\q uN"\n'),
    "syntax:binary": ("syntax", "\x00\x01\x02 = 3\n"),
    "syntax:not_utf8": ("syntax", b"normal_load = '\xff\xfe'\n"),
    "table:parameter": ("unknown table/key", '[parameter]\nnormal_load = "50 uN"\n'),
    "table:Run": ("unknown table/key", "[Run]\nsteps = 3\n"),
    "table:paramters": ("unknown table/key", "[paramters]\nnormal_load = 1e-5\n"),
    "table:top_level_param_table": ("unknown table/key", "[normal_load]\nvalue = 1e-5\n"),
    "key:normal_lod": ("unknown table/key", "normal_lod = 1e-5\n"),
    "key:in_parameters": ("unknown table/key", "[parameters]\nyoungs_modulu = 1e11\n"),
    "key:entry_valeu": ("unknown table/key", "[parameters.normal_load]\nvaleu = 1e-5\n"),
    "key:entry_extra": ("unknown table/key", "[parameters.normal_load]\nvalue = 1e-5\nnote = 'x'\n"),
    "key:run_stesp": ("unknown table/key", "[run]\nstesp = 5\n"),
    "type:bool": ("wrong type", "normal_load = true\n"),
    "type:list": ("wrong type", "[parameters]\nnormal_load = [1, 2]\n"),
    "type:inline_table": ("wrong type", "[parameters]\nmesh_steps = {a = 1}\n"),
    "type:string_for_int": ("wrong type", "[parameters]\nmesh_steps = 'many'\n"),
    "type:float_for_int": ("wrong type", "[parameters]\nteeth_pinion = 19.5\n"),
    "type:number_for_choice": ("wrong type", "[parameters]\nload_sharing = 5\n"),
    "type:date": ("wrong type", "[parameters]\nnormal_load = 1979-05-27\n"),
    "type:parameters_not_table": ("wrong type", "parameters = 5\n"),
    "type:run_not_table": ("wrong type", "run = 'fast'\n"),
    "type:entry_unit_number": ("wrong type", "[parameters.normal_load]\nvalue = 1\nunit = 5\n"),
    "type:entry_no_value": ("wrong type", "[parameters.normal_load]\nunit = 'N'\n"),
    "range:entry_unit": ("wrong type", "[parameters.normal_load]\nvalue = 50\nunit = 'kN'\n"),
}


def _config(body):
    def build(folder: Path):
        path = folder / "config.toml"
        path.write_bytes(body if isinstance(body, bytes) else body.encode("utf-8"))
        return ["constants", "--config", str(path), "--json"], "config.toml"
    return build


# --- study specs ------------------------------------------------------------------------------------------

_STUDIES = {
    "unknown_study_key": '[study]\nfunction = "gear"\ngrdi = {}\n[study.grid]\nseed = [1]\n',
    "unknown_point_key": '[study]\nfunction = "gear"\n[study.grid]\nnormal_lod = ["25 uN"]\n',
    "unknown_top_table": '[studdy]\nfunction = "gear"\n',
    "no_study_table": 'normal_load = "25 uN"\n',
    "no_points": '[study]\nfunction = "gear"\n',
    "empty_grid_list": '[study]\nfunction = "gear"\n[study.grid]\nnormal_load = []\n',
    "empty_grid_table": '[study]\nfunction = "gear"\n[study.grid]\n',
    "grid_not_table": '[study]\nfunction = "gear"\ngrid = 5\n',
    "points_not_list": '[study]\nfunction = "gear"\npoints = "all"\n',
    "point_not_table": '[study]\nfunction = "gear"\npoints = [1, 2]\n',
    "nested_list_value": '[study]\nfunction = "gear"\n[study.grid]\nnormal_load = [["25 uN"]]\n',
    "table_value_in_points": '[study]\nfunction = "gear"\n[[study.points]]\nnormal_load = {a = 1}\n',
    "name_not_text": '[study]\nname = 5\nfunction = "gear"\n[study.grid]\nseed = [1]\n',
    "function_not_text": '[study]\nfunction = 5\n[study.grid]\nseed = [1]\n',
    "function_os_system": '[study]\nfunction = "os:system"\n[study.grid]\nseed = [1]\n',
    "function_module_path": '[study]\nfunction = "memstribo.simulations.mesh:simulate_mesh"\n[study.grid]\nseed = [1]\n',
    "function_typo": '[study]\nfunction = "mseh"\n[study.grid]\nseed = [1]\n',
    "range_missing_num": '[study]\nfunction = "gear"\n[study.grid]\nnormal_load = {start = 1e-5, stop = 2e-5}\n',
    "range_num_zero": '[study]\nfunction = "gear"\n[study.grid]\nnormal_load = {start = 1e-5, stop = 2e-5, num = 0}\n',
    "range_num_huge": '[study]\nfunction = "gear"\n[study.grid]\nnormal_load = {start = 1e-5, stop = 2e-5, num = 10000000}\n',
    "range_num_float": '[study]\nfunction = "gear"\n[study.grid]\nnormal_load = {start = 1e-5, stop = 2e-5, num = 2.5}\n',
    "range_bad_unit": '[study]\nfunction = "gear"\n[study.grid]\nnormal_load = {start = "1 m", stop = "2 m", num = 2}\n',
    "too_many_points": ('[study]\nfunction = "gear"\n[study.grid]\nseed = {start = 0, stop = 1, num = 1000}\n'
                        "normal_load = {start = 1e-5, stop = 2e-5, num = 1000}\n"),
    "value_out_of_range": '[study]\nfunction = "gear"\n[study.grid]\nnormal_load = ["-5 uN"]\n',
    "unknown_coating": '[study]\nfunction = "mesh"\n[study.fixed]\ncoating = "OST"\n[study.grid]\nseed = [1]\n',
    "wear_without_coating": '[study]\nfunction = "mesh"\n[study.grid]\nwear = [0.5]\n',
    "wear_out_of_range": '[study]\nfunction = "mesh"\n[study.fixed]\ncoating = "OTS"\n[study.grid]\nwear = [1.5]\n',
    "steps_too_few": '[study]\nfunction = "mesh"\n[study.grid]\nsteps = [1]\n',
    "steps_huge": '[study]\nfunction = "mesh"\n[study.grid]\nsteps = [100000000]\n',
    "steps_memory": '[parameters]\nmesh_grid_spacing = "0.1 nm"\nmesh_window = "1.2 um"\n[study]\nfunction = "mesh"\n[study.grid]\nsteps = [90000]\n',
    "missing_roughness_file": '[study]\nfunction = "mesh"\n[study.grid]\nroughness = ["nope.txt"]\n',
    "run_table_in_spec": '[run]\nsteps = 5\n[study]\nfunction = "gear"\n[study.grid]\nseed = [1]\n',
    "bad_base_parameter": '[parameters]\nnormal_lod = 1\n[study]\nfunction = "gear"\n[study.grid]\nseed = [1]\n',
    "syntax_error": '[study\nfunction = "gear"\n',
    "seed_negative": '[study]\nfunction = "gear"\n[study.grid]\nseed = [-1]\n',
}


def _study(body):
    def build(folder: Path):
        path = folder / "spec.toml"
        path.write_text(body)
        return ["study", str(path), "--dry-run", "--json"], "spec.toml"
    return build


def _study_path(kind):
    def build(folder: Path):
        if kind == "missing":
            return ["study", str(folder / "missing.toml"), "--dry-run"], "missing.toml"
        return ["study", str(folder), "--dry-run"], folder.name
    return build


# --- parameters ---------------------------------------------------------------------------------------------

def _parameter_values(spec):
    """(label, value) pairs outside what ``spec`` allows."""
    values = []
    if spec.kind in ("float", "int"):
        lo, hi = spec.minimum, spec.maximum
        if lo is not None:
            if spec.kind == "int":
                below = lo - 1
            elif lo > 0:
                below = lo / 2
            elif lo == 0:
                below = 0.0 if spec.exclusive_minimum else -1.0
            else:
                below = lo * 2
            values.append(("below_min", repr(below)))
        if hi is not None:
            above = hi + 1 if spec.kind == "int" else (hi * 2 if hi > 0 else hi + 1)
            values.append(("above_max", repr(above)))
        values.append(("wrong_type", "abc"))
        values.append(("no_number", spec.unit if spec.unit else "%"))
        values.append(("wrong_dimension", "5 kg"))
        values.append(("nan", "nan"))
        if spec.kind == "int":
            values.append(("not_integer", "2.5" if (spec.minimum or 0) < 2.5 < (spec.maximum or 10) else "3.5"))
    elif spec.kind == "str":
        values.append(("not_a_choice", "dyr"))
    elif spec.kind == "bool":
        values.append(("not_bool", "maybe"))
    return values


def _set(name, value, command="constants"):
    def build(folder: Path):
        return [command, "--set", f"{name}={value}", "--json"], name
    return build


_ODD_UNITS = ["5 (uN", "5 uN/0", "uN", "5 uN uN", "5 uN)", "--5 uN", "5 uN\x1b[2J", "\uff15 uN", "5 \u00b5 N",
              "1e999 N", "0x10 N", "5 uN**", "5 uN^", "5 kg", "5 m/s", "5 degC", "nan uN", "inf N", "5 N N",
              "5e", "e5 N", "5 uN 3", "5,000 uN", "5 uN;rm -rf", "5 Å", "5 %"]

_OPTIONS = [
    ("slide_negative_load", ["slide", "--load", "-5uN"], "--load"),
    ("slide_huge_load", ["slide", "--load", "1e30"], "--load"),
    ("slide_gap_minus_1m", ["slide", "--gap", "-1 m"], "--gap"),
    ("slide_step_tiny", ["slide", "--step", "1e-20"], "--step"),
    ("slide_distance_huge", ["slide", "--distance", "1 m"], "1 m"),
    ("asperity_load_1e30", ["asperity", "--load", "1e30"], "--load"),
    ("asperity_load_word", ["asperity", "--load", "heavy"], "--load"),
    ("asperity_degree_zero", ["asperity", "--load", "1 uN", "--degree", "0"], "--degree"),
    ("resample_negative", ["roughness", "thesis", "--resample", "-1 nm"], "--resample"),
    ("resample_tiny", ["roughness", "thesis", "--resample", "1e-20"], "--resample"),
    ("resample_word", ["roughness", "thesis", "--resample", "fine"], "--resample"),
    ("unit_furlong", ["roughness", str(AFM / "si_profile_linescan.txt"), "--unit", "furlong"], "furlong"),
    ("channel_missing", ["roughness", str(AFM / "di-3.di"), "--channel", "Topo"], "Topo"),
    ("channel_not_height", ["roughness", str(AFM / "di-3.di"), "--channel", "Phase"], "Phase"),
    ("physical_size_bad", ["roughness", str(AFM / "di-3.di"), "--physical-size", "big"], "--physical-size"),
    ("physical_size_given_twice", ["roughness", str(AFM / "di-3.di"), "--physical-size", "1 um"], "--physical-size"),
    ("nanoblock_missing_file", ["nanoblock", "--from", "no_such_file.txt"], "no_such_file.txt"),
    ("outer_diameters_three", ["gear", "--outer-diameters", "1um,2um,3um"], "--outer-diameters"),
    ("outer_diameters_word", ["gear", "--outer-diameters", "a,b"], "--outer-diameters"),
    ("half_width_zero", ["constants", "--half-width", "0"], "--half-width"),
    ("half_width_huge", ["constants", "--half-width", "1 km"], "--half-width"),
    ("parameter_set_typo", ["constants", "--parameter-set", "silicon_thesys"], "silicon_thesys"),
    ("set_no_equals", ["constants", "--set", "normal_load"], "--set"),
    ("set_unknown", ["constants", "--set", "normal_lod=1"], "normal_lod"),
    ("config_missing", ["constants", "--config", "no_such.toml"], "no_such.toml"),
    ("damage_wear_points", ["damage", "--wear-points", "1"], "--wear-points"),
    ("damage_loads_word", ["damage", "--loads", "heavy"], "--loads"),
    ("damage_steps_huge", ["damage", "--steps", "100000000"], "--steps"),
    ("study_workers_zero", ["study", str(REPO / "examples" / "study_load_wear.toml"), "--workers", "0",
                            "--dry-run"], "--workers"),
    ("argparse_int", ["study", "x.toml", "--workers", "many"], "--workers"),
    ("argparse_missing_value", ["gear", "--set"], "--set"),
    ("pressure_angle_89", ["gear", "--set", "pressure_angle=89 deg"], "pressure_angle"),
]


def all_cases() -> list[Case]:
    from memstribo.parameters import SPECS

    cases: list[Case] = []
    for name in INSTRUMENT_FILES:
        for fraction in (0.1, 0.5, 0.99):
            if name.endswith(".ibw") and fraction == 0.99:
                # the last 1 % of this Igor wave lies beyond every section its header declares (wave, note,
                # units, labels): the cut leaves the heights and the ScanSize note whole, and the file reads
                # exactly as the whole one (checked: same JSON)
                cases.append(Case("truncated instrument file", f"{name}@99% (outside the declared sections)",
                                  _truncated(name, fraction), "same",
                                  lambda folder, n=name: ["roughness", str(AFM / n), "--json"]))
                continue
            cases.append(Case("truncated instrument file", f"{name}@{int(fraction * 100)}%",
                              _truncated(name, fraction)))
    for i, suffix in enumerate(EXTENSIONS):
        cases.append(Case("random bytes", suffix, _random_bytes(suffix, 1000 + i)))
        cases.append(Case("zero bytes", suffix, _zero_bytes(suffix)))
    for suffix in (".txt", ".csv"):
        for tag, body in _TEXT_ERRORS.items():
            cases.append(Case("bad text profile", f"{tag}{suffix}", _text_file(suffix, body, tag)))
        sep = "," if suffix == ".csv" else " "
        for tag, body in _TEXT_SAME.items():
            cases.append(Case("encoding / line ends (read correctly)", f"{tag}{suffix}",
                              _text_file(suffix, (lambda b=body, s=sep: b(s)), tag), "same", _reference(suffix)))
    for name, (kind, body) in _CONFIGS.items():
        cases.append(Case(f"config: {kind}", name, _config(body)))
    for name, body in _STUDIES.items():
        cases.append(Case("bad study spec", name, _study(body)))
    cases.append(Case("bad study spec", "missing_file", _study_path("missing")))
    cases.append(Case("bad study spec", "folder", _study_path("folder")))
    for name, spec in SPECS.items():
        for label, value in _parameter_values(spec):
            kind = "parameter out of range" if label in ("below_min", "above_max") else "parameter wrong type/no number"
            cases.append(Case(kind, f"{name}={label}", _set(name, value)))
    for text in _ODD_UNITS:
        cases.append(Case("odd unit string", repr(text), _set("normal_load", text)))
    for name, argv, needle in _OPTIONS:
        cases.append(Case("bad command-line option", name, (lambda folder, a=argv, n=needle: (a + ["--json"], n))))
    return cases


# --- checking -----------------------------------------------------------------------------------------------

_CONTROL = re.compile(r"[\x00-\x08\x0b-\x1f\x7f-\x9f]")
_QUOTED = re.compile(r"'[^'\n]*'|\"[^\"\n]*\"")
#: NaN or infinity as a result value: any NaN/Infinity token in stdout (JSON or text); in a message, a
#: NaN or inf shown as a value (after '=' or ':', or before a unit) outside the quoted echo of an input
_NAN_OUT = re.compile(r"(?<![A-Za-z])[-+]?(nan|inf|infinity)(?![A-Za-z])", re.IGNORECASE)
_NAN_VALUE = re.compile(r"(?:[=:]\s*|\bis\s+|\bgot\s+)[-+]?(nan|inf|infinity)\b|\b[-+]?(nan|inf)\s+(m|N|Pa|J|s|rad)\b",
                        re.IGNORECASE)


def _json_error_matches(out, err):
    """Under --json an error is one JSON object on stdout with the stderr message as "error" (#29)."""
    import json

    try:
        value = json.loads(out)
    except ValueError:
        return False
    return isinstance(value, dict) and set(value) >= {"error", "parameter"} and value["error"] in err


def run_case(case: Case, folder: Path, main, capture) -> tuple[str, str]:
    """Run one case: (outcome, detail). Outcomes: 'clean error', 'read correctly', 'internal error',
    'traceback', 'silent wrong output', 'bad message'."""
    folder.mkdir(parents=True, exist_ok=True)
    argv, needle = case.build(folder)
    try:
        code = main(argv)
    except SystemExit as exc:  # argparse
        code = exc.code
    except BaseException as exc:  # noqa: BLE001 - anything escaping main is a traceback for the user
        capture()
        return "traceback", f"{type(exc).__name__}: {exc}"
    out, err = capture()
    if "Traceback" in out + err:
        return "traceback", err[-300:]
    if "internal error" in err:
        return "internal error", err[-300:]
    shown = "" if _json_error_matches(out, err) else out  # a JSON error repeats the message (it may quote 'nan')
    if _NAN_OUT.search(shown) or _NAN_VALUE.search(_QUOTED.sub("", err)):
        return "silent wrong output", (out + err)[:300]
    if case.expect == "same":
        if code != 0:
            return "bad message", f"exit {code}: {err[:300]}"
        import json

        ref_code = main(case.reference(folder))
        ref_out, ref_err = capture()
        got, want = json.loads(out), json.loads(ref_out)
        for key in ("name", "source"):
            got.pop(key, None), want.pop(key, None)
        if ref_code != 0 or got != want:
            return "silent wrong output", f"differs from the plain file: {ref_err[:200]}"
        return "read correctly", ""
    if code != 2:
        return "silent wrong output", f"exit {code}: {(out + err)[:300]}"
    lines = err.strip().splitlines()
    problems = []
    if not (1 <= len(lines) <= MAX_LINES):
        problems.append(f"{len(lines)} lines")
    if len(err.strip()) > MAX_CHARS:
        problems.append(f"{len(err.strip())} chars")
    if _CONTROL.search(err):
        problems.append("control characters")
    if needle not in err:
        problems.append(f"does not name {needle!r}")
    if out.strip() and not _json_error_matches(out, err):
        problems.append("stdout not empty (nor, under --json, the error as one JSON object)")
    if problems:
        return "bad message", "; ".join(problems) + ": " + err[:400]
    return "clean error", ""


def main_table() -> str:  # pragma: no cover - the script that writes the docs/hardening.md table
    import contextlib
    import io
    import tempfile
    from collections import Counter, defaultdict

    from memstribo.cli.main import main

    counts: dict[str, Counter] = defaultdict(Counter)
    buffers = {"out": io.StringIO(), "err": io.StringIO()}

    def capture():
        out, err = buffers["out"].getvalue(), buffers["err"].getvalue()
        for b in buffers.values():
            b.seek(0), b.truncate()
        return out, err

    failures = []
    with tempfile.TemporaryDirectory() as tmp:
        for i, case in enumerate(all_cases()):
            with contextlib.redirect_stdout(buffers["out"]), contextlib.redirect_stderr(buffers["err"]):
                outcome, detail = run_case(case, Path(tmp) / f"c{i}", main, capture)
            counts[case.kind][outcome] += 1
            if outcome not in ("clean error", "read correctly"):
                failures.append(f"{case.id}: {outcome}: {detail}")
    columns = ["clean error", "read correctly", "internal error", "traceback", "silent wrong output", "bad message"]
    lines = ["| kind of input | tried | " + " | ".join(columns) + " |", "|---|---|" + "---|" * len(columns)]
    total = Counter()
    for kind, counter in counts.items():
        total.update(counter)
        lines.append(f"| {kind} | {sum(counter.values())} | " + " | ".join(str(counter[c]) for c in columns) + " |")
    lines.append(f"| **all** | **{sum(total.values())}** | " + " | ".join(f"**{total[c]}**" for c in columns) + " |")
    return "\n".join(lines + [""] + failures)


if __name__ == "__main__":  # pragma: no cover
    print(main_table())
