"""Published adhesion energies of hydrophilic polysilicon microbeams against RH, as data (issue #36 item 2).

What the searched records state, word for word where quoted, with its source key (:mod:`memstribo.references`).
Numbered Gamma(RH) points of these papers (their figures) were not found in the searched records: the data are the
upper limit the energy approaches, the low-RH plateau and the rise, each compared with the model of
:mod:`memstribo.physics.rough_capillary` in tests/test_rough_capillary.py. A point read from a figure belongs here
with its figure number once the paper is at hand.
"""

from __future__ import annotations

__all__ = ["MICROBEAM_HUMIDITY"]

#: One record per published statement: source (a reference key), kind ("upper limit": the energy [J/m^2] the beams
#: approach as RH rises towards saturation; "plateau": constant below a threshold RH; "rise": grows over an RH
#: range), the numbers the statement carries (SI) and its words.
MICROBEAM_HUMIDITY = (
    {"source": "delrio_2007", "kind": "upper limit", "adhesion_energy": 0.144, "relative_humidity": (0.95, 1.0),
     "surface": "hydrophilic polysilicon microcantilevers (crack-length method), several roughnesses",
     "text": "Above the threshold RH, the adhesion jumps due to capillary condensation and increases towards the "
             "upper limit of Gamma = 144 mJ/m^2 (abstract; 2 gamma of water, contact angle 0)"},
    {"source": "delrio_2007", "kind": "plateau", "relative_humidity": (0.0, 0.3),
     "surface": "hydrophilic polysilicon microcantilevers",
     "text": "Below a threshold RH, the adhesion is mainly due to van der Waals forces across extensive noncontacting "
             "areas (abstract; the range 0-0.3 is where this project's done-when criterion reads it)"},
    {"source": "langmuir_2009_rough_capillary", "kind": "plateau", "relative_humidity": (0.0, 0.3),
     "surface": "rough surfaces (microbeam experiments summarised)",
     "text": "the adhesion energy remains constant below a critical relative humidity (RHcr) and then abruptly jumps "
             "to a higher value at RHcr before approaching its upper limit at 100% relative humidity (abstract)"},
    {"source": "deboer_1998", "kind": "rise", "relative_humidity": (0.3, 0.95),
     "surface": "hydrophilic (oxygen-plasma treated) polysilicon microbeams",
     "text": "adhesion increases exponentially with RH (abstract); crack lengths decreased spontaneously with "
             "increasing humidity from 30 to 95% RH (the group's later citing statement)"},
)
