"""The numbers of the acceptance rules (``docs/formats.md``), in one place.

The validator (:mod:`lgmcts.validate`) and each pattern's acceptance rule
(``accept`` in :mod:`lgmcts.patterns`) read them from here; the planner keeps
its own, tighter margins (:data:`lgmcts.patterns.base.BAND`, ``CLEARANCE``).
"""

from __future__ import annotations

import math

#: Distance of a centre from its fitted curve or target (m).
TOL = 0.015
#: Largest overlap of two table footprints counted as contact (m²).
OVERLAP_AREA = 1e-6
#: Largest xy offset of a tower level from the one below (m).
TOWER_TOL = 0.02
#: Largest anchor-to-object distance of a spatial relation (m).
MAX_RELATION_DIST = 0.30
#: Largest angle between the anchor-to-object vector and the relation's direction (rad).
RELATION_HALF_ANGLE = math.pi / 4
#: Largest yaw error of a pose goal (rad).
POSE_ANGLE_TOL = 0.1
#: Smallest fitted radius of a circle (m).
MIN_CIRCLE_RADIUS = 0.05
#: Shortest side of a rectangle (m).
MIN_RECT_SIDE = 0.05
