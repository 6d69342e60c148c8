"""Fuzz the command line with bad inputs (issues #14, #15): every one a short, clean error (exit 2).

The cases are in tests/fuzz_cases.py (``python tests/fuzz_cases.py`` prints the counts table of
docs/hardening.md): each shipped instrument file truncated at 10/50/99 %, zero and random bytes
per extension, bad text profiles (NaN/inf, non-monotonic or duplicate x, 1-2 points, huge values,
wrong delimiters, control characters), BOM/UTF-16/CR files (read correctly), TOML syntax errors,
unknown tables and keys, wrong types, bad study specs, every parameter below its minimum, above
its maximum, of the wrong type and without a number, odd unit strings and bad option values.
Each must end in exit status 2 with at most 5 lines / 600 characters on stderr that name the
file or parameter, hold no control characters, no "Traceback", no "internal error" and no NaN or
infinity shown as a value, and print nothing on stdout; the "read correctly" cases must give the
same JSON as the plain file.
"""

from __future__ import annotations

import subprocess
import sys
from collections import Counter

import pytest

from fuzz_cases import AFM, all_cases, run_case

CASES = all_cases()


@pytest.fixture(scope="module")
def main():
    from memstribo.cli.main import main

    return main


@pytest.mark.parametrize("case", CASES, ids=[c.id for c in CASES])
def test_bad_input_is_a_clean_error(case, main, capsys, tmp_path):
    def capture():
        captured = capsys.readouterr()
        return captured.out, captured.err

    outcome, detail = run_case(case, tmp_path, main, capture)
    expected = "read correctly" if case.expect == "same" else "clean error"
    assert outcome == expected, detail


def test_every_kind_the_issue_asks_for_is_covered():
    from memstribo.parameters import SPECS

    kinds = Counter(c.kind for c in CASES)
    assert kinds["truncated instrument file"] == 3 * len([p for p in AFM.iterdir() if p.name != "README.md"])
    assert kinds["random bytes"] >= 20 and kinds["zero bytes"] >= 20
    assert kinds["bad text profile"] >= 40 and kinds["encoding / line ends (read correctly)"] >= 6
    assert sum(n for k, n in kinds.items() if k.startswith("config:")) >= 25
    assert kinds["bad study spec"] >= 30 and kinds["odd unit string"] >= 20
    names = {c.name.split("=")[0] for c in CASES if c.kind.startswith("parameter")}
    assert names == set(SPECS)
    numeric = [s for s in SPECS.values() if s.kind in ("float", "int")]
    assert kinds["parameter out of range"] == 2 * len(numeric)
    assert len(CASES) >= 500


@pytest.mark.parametrize("argv, needle", [
    (["roughness", "{tmp}/random.tiff"], "random.tiff"),
    (["gear", "--set", "pressure_angle=89 deg"], "pressure_angle"),
])
def test_real_subprocess(tmp_path, argv, needle):
    (tmp_path / "random.tiff").write_bytes(b"II*\x00" + bytes(range(256)) * 8)
    argv = [a.replace("{tmp}", str(tmp_path)) for a in argv]
    result = subprocess.run([sys.executable, "-m", "memstribo.cli.main", *argv], capture_output=True, text=True,
                            timeout=120)
    assert result.returncode == 2, result.stderr
    assert needle in result.stderr and "Traceback" not in result.stderr and "internal error" not in result.stderr
    assert len(result.stderr.strip().splitlines()) <= 5 and not result.stdout
