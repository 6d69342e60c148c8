"""Materials as data (issue 37 item 3): silicon nitride and silica with priors and sources, DDMS accepted."""

import math

import pytest

from memstribo.errors import InputError
from memstribo.laboratory import predict
from memstribo.laboratory.data import Measurement
from memstribo.laboratory.materials import MATERIALS, material_priors, material_table, pair_overrides, row_parameters
from memstribo.parameters import get_parameter_values
from memstribo.uncertainty.priors import coating_priors


def test_every_material_constant_has_a_source_and_a_prior_around_its_value():
    table = material_table()
    assert {"silicon_nitride", "silica"} <= set(table)
    for name, entry in table.items():
        priors = material_priors(name)
        for prop, item in entry.items():
            assert item["source"].strip(), (name, prop)
            prior = priors[prop]
            assert prior.source and prior.reason
            assert prior.low <= float(item["value"]) <= prior.high, (name, prop)


def test_nitride_against_silicon_and_against_itself():
    params = get_parameter_values("silicon_thesis")
    against_silicon = pair_overrides(params, "silicon_nitride", "silicon")
    itself = pair_overrides(params, "silicon_nitride", "silicon_nitride")
    nitride = material_table()["silicon_nitride"]
    assert against_silicon["youngs_modulus"] == nitride["youngs_modulus"]["value"]
    assert against_silicon["counter_youngs_modulus"] == params["youngs_modulus"]
    assert against_silicon["hamaker_constant"] == pytest.approx(
        math.sqrt(nitride["hamaker_constant"]["value"] * params["hamaker_constant"]))
    assert against_silicon["hardness"] == min(params["hardness"], nitride["hardness"]["value"])
    assert itself["hamaker_constant"] == pytest.approx(nitride["hamaker_constant"]["value"])
    assert itself["counter_youngs_modulus"] == itself["youngs_modulus"]
    assert pair_overrides(params, "polysilicon", "silicon") == {}
    with pytest.raises(InputError, match="counter_material"):
        pair_overrides(params, "silicon", "diamond")
    assert set(MATERIALS) == {"polysilicon", "silicon", "silica", "silicon_nitride"}


def _row(**fields):
    conditions = {"geometry": "sphere_on_flat", "environment": "vacuum", "coating": "none", "sphere_radius": 1e-6,
                  "normal_force": 1e-6, "surface": "x"}
    conditions.update(fields)
    return Measurement(id="m", quantity="kinetic_cof", value=0.2, unit="1", scatter={"kind": "sd", "value": 0.02},
                       calibration=False, citation="thesis", conditions=conditions)


def test_ddms_is_accepted_with_its_priors():
    """DDMS used to be refused by predict.row_values (only OTS and FDTS were let through); it ships with priors."""
    assert set(coating_priors("DDMS")) == {"coating_vdw_bond_energy", "coating_work_of_adhesion"}
    p = predict.predict_row(_row(coating="DDMS"), realisations=1)
    assert p.status == "predicted", p.reason
    params, _ = row_parameters(_row(coating="DDMS"))
    assert params["bond_energy"] == 1e-21 and params["water_contact_angle"] == pytest.approx(math.radians(103))


def test_a_nitride_row_is_predicted_with_the_nitride_constants():
    params, _ = row_parameters(_row(material="silicon_nitride", counter_material="silicon"))
    assert params["youngs_modulus"] == material_table()["silicon_nitride"]["youngs_modulus"]["value"]
    assert predict.predict_row(_row(material="silicon_nitride"), realisations=1).status == "predicted"
