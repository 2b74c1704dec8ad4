"""``artimo bench run`` and ``artimo bench evaluate``."""

from __future__ import annotations

import argparse
import json
from pathlib import Path
from typing import Any

from app.cli.model_options import add_model_options, engine_overrides, provider_config
from app.cli.output import cache_dir, err, out


def register(commands: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    bench = commands.add_parser("bench", help="benchmark: animate annotated cases and score them")
    sub = bench.add_subparsers(dest="bench_command", required=True, metavar="SUBCOMMAND")

    run = sub.add_parser("run", help="animate every case with a provider, then evaluate")
    _common(run)
    run.add_argument("--out", type=Path, required=True, help="folder for OUT/<case_id>/ outputs, evaluation.json and report/")
    add_model_options(run)
    run.set_defaults(handler=_run)

    critic = sub.add_parser("critic", help="inject known failures into correct plans; report critic detection and repair per class")
    critic.add_argument("--cases", type=Path, required=True, help="JSON Lines, one case per line (SPEC §5)")
    critic.add_argument("--assets", type=Path, required=True, help="folder holding the cases' asset folders")
    critic.add_argument("--out", type=Path, default=None, help="write the results as JSON (classes, cases)")
    critic.add_argument("--jobs", type=int, default=1, help="worker processes (results do not depend on it)")
    critic.add_argument("--rounds", type=int, default=3, help="critic-actor repair rounds (default 3)")
    critic.add_argument("--class", dest="classes", action="append", default=[], metavar="CODE", help="only these failure classes (repeatable)")
    add_model_options(critic)
    critic.set_defaults(handler=_critic)

    evaluate = sub.add_parser("evaluate", help="score existing predictions PRED/<case_id>/trajectory.jsonl (or animation.glb)")
    _common(evaluate)
    evaluate.add_argument("--pred", type=Path, required=True)
    evaluate.add_argument("--out", type=Path, required=True, help="OUT.json")
    evaluate.add_argument("--node-map", type=Path, default=None, help="JSON mapping GLB node names to links (third-party GLBs)")
    evaluate.set_defaults(handler=_evaluate)


def _common(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--cases", type=Path, required=True, help="JSON Lines, one case per line")
    parser.add_argument("--assets", type=Path, default=None,
                        help="folder holding the cases' asset folders (default: $ARTIMO_PARTNET_ROOT, else "
                             "../shared/assets/partnet beside this repository)")
    parser.add_argument("--allow-failures", action="store_true",
                        help="exit 0 even when cases fail to animate or cannot be scored (default: exit 1)")
    parser.add_argument("--jobs", type=int, default=2, help="worker processes (results do not depend on it)")
    parser.add_argument("--with-2d", action="store_true", help="also P_MaskIoU / P_BoundaryF1 / P_ContourCD (renders through EGL)")
    parser.add_argument("--no-report", action="store_true", help="skip report.md, CSVs and charts")
    parser.add_argument("--contact-sheets", action="store_true", help="render GT vs predicted key states per case into the report")


def _print_summary(document: dict[str, Any]) -> None:
    summary = document["summary"]
    out(json.dumps({k: v for k, v in summary.items() if k != "settings"}, indent=2))


def _report(args: argparse.Namespace, out_json: Path, pred: Path) -> None:
    if args.no_report:
        return
    from benchmark.report import write_report

    path = write_report(out_json, out_json.parent / "report", contact_sheets=args.contact_sheets, cases_file=args.cases,
                        assets_root=args.assets, pred_root=pred, node_map=getattr(args, "node_map", None))
    out(f"report     {path}")


def _assets_root(args: argparse.Namespace) -> Path:
    """``--assets`` or the PartNet root, checked against the cases (a root holding none of them is an error)."""
    from benchmark.cases import read_cases
    from benchmark.paths import check_assets_root, partnet_root

    root = args.assets if args.assets is not None else partnet_root()
    missing = check_assets_root(root, (case.asset for case in read_cases(args.cases)), str(args.cases))
    for name in missing:
        err(f"missing asset: {root / name}")
    args.assets = root
    return root


def _failures(document: dict[str, Any]) -> int:
    """Cases that were not scored (no prediction, an unreadable one, or a case error)."""
    return sum(count for status, count in document["summary"]["by_status"].items() if status != "scored")


def _verdict(args: argparse.Namespace, failed: int, total: int, what: str) -> int:
    if not failed:
        return 0
    err(f"{failed} of {total} cases {what}" + ("; exit 0 (--allow-failures)" if args.allow_failures else "; exit 1 (--allow-failures to tolerate)"))
    return 0 if args.allow_failures else 1


def _evaluate(args: argparse.Namespace) -> int:
    from benchmark.runner import evaluate

    _assets_root(args)
    document = evaluate(args.cases, args.assets, args.pred, args.out, node_map=args.node_map, with_2d=args.with_2d, jobs=args.jobs,
                        cache_dir=cache_dir(args))
    _print_summary(document)
    out(f"scores     {args.out}")
    _report(args, args.out, args.pred)
    return _verdict(args, _failures(document), len(document["cases"]), "were not scored")


def _run(args: argparse.Namespace) -> int:
    from app.engine.config import EngineConfig
    from benchmark.run import animate_cases
    from benchmark.runner import evaluate

    _assets_root(args)
    config = EngineConfig(asset_cache_dir=cache_dir(args), **engine_overrides(args))
    records = animate_cases(args.cases, args.assets, args.out, provider=args.provider, provider_config=provider_config(args), config=config, jobs=args.jobs)
    failed = [r for r in records if r["status"] != "ok"]
    out(f"animated   {len(records) - len(failed)}/{len(records)} cases ({len(failed)} failed; see {args.out / 'runs.json'})")
    out_json = args.out / "evaluation.json"
    document = evaluate(args.cases, args.assets, args.out, out_json, with_2d=args.with_2d, jobs=args.jobs, cache_dir=cache_dir(args))
    _print_summary(document)
    out(f"scores     {out_json}")
    _report(args, out_json, args.out)
    return _verdict(args, max(len(failed), _failures(document)), len(records), "failed (animation or scoring)")


def _critic(args: argparse.Namespace) -> int:
    from app.engine.config import EngineConfig
    from app.engine.errors import MetricError
    from app.engine.files import atomic_write_text
    from benchmark.critic_bench import critic_bench, table_lines
    from benchmark.critic_injection import CLASSES

    unknown = [c for c in args.classes if c not in CLASSES]
    if unknown:
        raise MetricError(f"unknown failure class(es) {', '.join(unknown)} (classes: {', '.join(CLASSES)})")
    config = EngineConfig(asset_cache_dir=cache_dir(args), **engine_overrides(args))
    document = critic_bench(args.cases, args.assets, provider=args.provider, provider_config=provider_config(args), config=config,
                            max_rounds=args.rounds, classes=tuple(args.classes) or CLASSES, jobs=args.jobs)
    for line in table_lines(document):
        out(line)
    errors = [c for c in document["cases"] if c.get("class") == "case_error"]
    if errors:
        out(f"{len(errors)} case(s) could not be run: " + "; ".join(f"{c['case_id']}: {c['error']}" for c in errors[:3]))
    if args.out is not None:
        atomic_write_text(args.out, json.dumps(document, indent=2) + "\n")
        out(f"results    {args.out}")
    return 0
