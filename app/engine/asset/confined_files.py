"""Files a mesh refers to (an OBJ's ``mtllib``, an MTL's textures), read only from inside the asset.

Both mesh readers go through :class:`ConfinedFiles`: the built-in OBJ reader directly, the trimesh
path through a resolver that wraps it. Every name resolves relative to the mesh file's folder and
must stay inside the asset root; every file read passes :func:`check_image` (a texture may hide
under any name) before a reader sees its bytes.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

from app.engine.asset.safety import AssetLimits, check_image
from app.engine.errors import AssetError

ESCAPES = " escapes the asset directory"
MISSING = " is missing"


@dataclass
class ConfinedFiles:
    """Read files named by a mesh file, never outside ``root``.

    Attributes
    ----------
    parent : Path
        The folder names resolve against (the mesh file's folder).
    root : Path
        The asset root (resolved).
    report : list of str
        ``'name' is missing`` / ``'name' escapes the asset directory``, one per failed read, in order.
    refused : list of AssetError
        Files refused by :func:`check_image`; a reader that swallows errors leaves them here for the caller.
    """

    parent: Path
    root: Path
    limits: AssetLimits = field(default_factory=AssetLimits)
    report: list[str] = field(default_factory=list)
    refused: list[AssetError] = field(default_factory=list)

    @classmethod
    def beside(cls, mesh_file: Path, root: Path, limits: AssetLimits | None = None) -> ConfinedFiles:
        """Files named relative to ``mesh_file``'s folder."""
        return cls(parent=mesh_file.parent, root=root, limits=limits or AssetLimits())

    def get(self, name: str) -> bytes:
        """The bytes of the file ``name`` (relative to :attr:`parent`).

        Raises
        ------
        FileNotFoundError
            The name escapes the asset or names no file (recorded in :attr:`report`).
        AssetError
            The file is an image over the pixel limit (recorded in :attr:`refused`).
        """
        candidate = (self.parent / name.strip().replace("\\", "/")).resolve()
        if not candidate.is_relative_to(self.root):
            self.report.append(f"'{name}'{ESCAPES}")
            raise FileNotFoundError(name)
        if not candidate.is_file():
            self.report.append(f"'{name}'{MISSING}")
            raise FileNotFoundError(name)
        data = candidate.read_bytes()
        try:
            check_image(data, str(candidate.relative_to(self.root)), self.limits)  # a texture under any name: header first
        except AssetError as exc:
            self.refused.append(exc)
            raise
        return data

    def raise_problems(self, relative: str) -> list[str]:
        """After a mesh is read: raise the first refusal or escape, else return the warnings to keep.

        Raises
        ------
        AssetError
            A referenced file was refused, or a reference leaves the asset directory.
        """
        if self.refused:
            raise self.refused[0]
        escapes = [r for r in self.report if r.endswith(ESCAPES)]
        if escapes:
            names = "; ".join(r.removesuffix(ESCAPES) for r in escapes)
            raise AssetError("mesh references a file outside the asset directory: " + "; ".join(escapes), file=relative,
                             element=f"reference {names}")
        return [f"{relative}: referenced file {r}" for r in self.report]
