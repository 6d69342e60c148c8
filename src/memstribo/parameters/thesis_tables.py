"""The thesis's printed tables that memstribo is compared with, as data (SI units).

Copied digit for digit from the thesis (chapter 5, section 5.5.2); used as inputs
(``memstribo damage --loads table5-1``), by the validation rows and by the tests. The rows
of Tables 5-1 and 5-2 are the six nanoblock loads the thesis studies.
"""

from __future__ import annotations

import numpy as np

#: Table 5-1: nanoblock load and the loads of its corner / side / central atomic asperities [N].
TABLE_5_1 = np.array([
    [0.8166, 0.0963, 0.0884, 0.0782],
    [0.99, 0.1167, 0.1071, 0.0947],
    [1.7944, 0.2115, 0.1941, 0.1717],
    [3.4279, 0.4041, 0.3709, 0.3281],
    [4.4055, 0.5193, 0.4766, 0.4216],
    [7.0165, 0.8275, 0.7595, 0.6719],
]) * 1e-6

#: Table 5-1's nanoblock loads [N] (its first column).
TABLE_5_1_LOADS = TABLE_5_1[:, 0].copy()

#: Table 5-2: contact radii of the corner / side / central asperities at the loads of Table 5-1 [m].
TABLE_5_2 = np.array([
    [5.82, 5.72, 5.59], [6.05, 5.94, 5.80], [6.82, 6.70, 6.52],
    [7.76, 7.62, 7.44], [8.16, 8.02, 7.82], [8.95, 8.80, 8.59],
]) * 1e-9

#: Table 5-3 (damage exponent m = 1): max omega/c1 [Pa] and its location x [m], per asperity position.
TABLE_5_3 = {"corner": (0.248e11, -0.823e-8), "side": (0.243e11, -0.801e-8), "central": (0.226e11, -0.7791e-8)}

#: Table 5-4 (m = 2): max omega/c1 [Pa^2] and its location x [m], per asperity position.
TABLE_5_4 = {"corner": (0.1706082e20, -0.81801e-8), "side": (0.1607712e20, -0.79900e-8),
             "central": (0.1387791e20, -0.77999e-8)}
