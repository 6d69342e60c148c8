"""memstribo.output: datasets to NetCDF + CSV, JSON without NaN."""

import json
import math

import numpy as np
import pytest
import xarray as xr

from memstribo.output import dumps_json, write_dataset


def test_csv_is_the_table_along_the_main_dimension(tmp_path):
    steps, blocks = 5, 40
    dataset = xr.Dataset(
        {
            "cof": ("step", np.linspace(0.1, 0.5, steps), {"units": ""}),
            "friction_force": ("step", np.arange(steps) * 1e-6, {"units": "N"}),
            "block_load": (("step", "block"), np.ones((steps, blocks)), {"units": "N"}),
        },
        coords={"step": np.arange(steps), "block": np.arange(blocks)},
    )
    nc, csv = write_dataset(dataset, tmp_path, "run")
    lines = [line for line in csv.read_text().splitlines() if not line.startswith("#")]  # provenance block
    assert lines[0] == "step [1],cof [1],friction_force [N]"
    assert len(lines) == steps + 1  # not steps * blocks rows
    again = xr.load_dataset(nc)
    assert again["block_load"].shape == (steps, blocks)  # NetCDF keeps everything
    assert again["friction_force"].attrs["units"] == "N"


def test_json_has_no_nan():
    text = dumps_json({"a": np.float64(1.5), "b": math.nan, "c": np.arange(2), "d": np.bool_(True)})
    assert json.loads(text) == {"a": 1.5, "b": None, "c": [0, 1], "d": True}


def test_unwritable_folder_is_an_input_error(tmp_path):
    from memstribo.errors import InputError
    from memstribo.output import ensure_directory

    blocker = tmp_path / "file"
    blocker.write_text("x")
    with pytest.raises(InputError, match="cannot create output folder"):
        ensure_directory(blocker / "sub")
