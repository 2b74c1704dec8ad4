"""Write a run's outputs into a hidden folder, then move them in place together.

A run (``run_pipeline``, ``run_plan``) never writes into its output folder directly: it
writes into ``OUT/.artimo-partial-<random>/`` and, when it ends (successfully or with a
failure report), :meth:`Staging.publish` replaces every output of an earlier run in
``OUT`` with the new set. An earlier run's ``animation.glb`` therefore never stays beside a
new run's failure report, and a reader never sees a half-written set: ``report.json`` is
removed first and moved in last. Files in ``OUT`` that are not run outputs are left alone.
"""

from __future__ import annotations

import logging
import os
import secrets
import shutil
from pathlib import Path

logger = logging.getLogger(__name__)

PARTIAL_PREFIX = ".artimo-partial-"
RUN_OUTPUTS = ("causal.json", "plan.json", "trajectory.jsonl", "animation.glb", "interaction.json", "animation.usda", "usd_textures", "scene.xml",
               "joint_trajectory.json", "trajectory.csv", "trajectory.npz", "preview.gif", "images", "keyframes", "report.json")
"""Every entry a run may write into its output folder (``report.json`` last: it marks a complete set)."""
MARKER = "report.json"


def _remove(path: Path) -> None:
    if path.is_dir() and not path.is_symlink():
        shutil.rmtree(path)
    elif path.exists() or path.is_symlink():
        path.unlink()


class Staging:
    """A hidden folder inside ``out_dir`` for one run's outputs.

    Use as a context manager: the folder is removed on exit whatever happened; call
    :meth:`publish` before that to move its content into ``out_dir``.
    """

    def __init__(self, out_dir: str | Path) -> None:
        self.out_dir = Path(out_dir)
        self.out_dir.mkdir(parents=True, exist_ok=True)
        self.path = self.out_dir / f"{PARTIAL_PREFIX}{secrets.token_hex(6)}"
        self.path.mkdir()
        self.published = False

    def __enter__(self) -> Staging:
        return self

    def __exit__(self, *_: object) -> None:
        self.discard()

    def publish(self, *, only: tuple[str, ...] | None = None) -> list[str]:
        """Replace the previous run's outputs in ``out_dir`` with the staged ones (or just ``only`` of them: a
        failed run publishes its report alone); returns the names moved."""
        staged = sorted(p.name for p in self.path.iterdir() if only is None or p.name in only)
        stale = self.out_dir / MARKER
        if stale.exists():
            stale.unlink()
        for name in RUN_OUTPUTS:
            if name not in staged and name != MARKER:
                _remove(self.out_dir / name)
        for name in [n for n in staged if n != MARKER] + ([MARKER] if MARKER in staged else []):
            source, target = self.path / name, self.out_dir / name
            if source.is_dir():
                if target.exists() or target.is_symlink():
                    trash = self.path / f".old-{name}"
                    os.replace(target, trash)
                os.replace(source, target)
            else:
                if target.is_dir() and not target.is_symlink():
                    shutil.rmtree(target)
                os.replace(source, target)
        self.published = True
        logger.debug("published %d outputs into %s", len(staged), self.out_dir)
        return staged

    def discard(self) -> None:
        """Remove the staging folder (and anything left in it)."""
        shutil.rmtree(self.path, ignore_errors=True)
