"""Array aliases used across the engine (shapes in the names' docstrings).

All arrays are ``float64`` unless stated otherwise.
"""

from __future__ import annotations

from typing import TypeAlias

import numpy as np
from numpy.typing import NDArray

FloatArray: TypeAlias = NDArray[np.float64]
IntArray: TypeAlias = NDArray[np.int64]
Transform: TypeAlias = NDArray[np.float64]
"""(4, 4) homogeneous rigid transform; maps child-frame points to parent frame."""
Transforms: TypeAlias = NDArray[np.float64]
"""(t, 4, 4) stack of transforms, one per frame."""
Points: TypeAlias = NDArray[np.float64]
"""(n, 3) points, metres."""
Vector3: TypeAlias = NDArray[np.float64]
"""(3,) vector."""
JointMatrix: TypeAlias = NDArray[np.float64]
"""(t, j) joint values per frame; radians (revolute/continuous) or metres (prismatic)."""
