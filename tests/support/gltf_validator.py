"""The Khronos glTF-Validator for the tests: :mod:`app.gltf_validation` (also ``artimo validate-glb``).

Command line: ``python -m tests.support.gltf_validator FILE.glb ...`` prints the reports and
exits 1 unless every file has 0 errors and 0 warnings.
"""

from __future__ import annotations

import sys

from app import gltf_validation
from app.gltf_validation import (
    INSTALL_COMMAND,
    ValidationReport,
    ValidatorUnavailable,
    assert_valid,
    main,
    validate_glb,
)

__all__ = ["INSTALL_COMMAND", "ValidationReport", "ValidatorUnavailable", "assert_valid", "gltf_validation", "main", "validate_glb"]

if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
