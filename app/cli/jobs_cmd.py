"""``artimo jobs list|show|download|cancel``: your jobs on an ArtiMo server."""

from __future__ import annotations

import argparse
from pathlib import Path
from typing import TYPE_CHECKING, Any

from app.cli.output import err, out, out_json
from app.cli.server_options import add_server_options, open_client

if TYPE_CHECKING:
    from app.client import ArtimoClient

STATUSES = ("queued", "running", "succeeded", "failed", "cancelled")


def register(commands: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    jobs = commands.add_parser("jobs", help="list, show, download or cancel your jobs on an ArtiMo server")
    actions = jobs.add_subparsers(dest="jobs_command", required=True, metavar="ACTION")
    listing = actions.add_parser("list", help="your jobs, newest first")
    add_server_options(listing)
    listing.add_argument("--status", choices=STATUSES, default=None)
    listing.add_argument("--limit", type=int, default=20)
    listing.add_argument("--offset", type=int, default=0)
    listing.add_argument("--json", action="store_true", help="the server's answer as JSON")
    listing.set_defaults(handler=_list)
    show = actions.add_parser("show", help="one job: status, stage, progress, error, timings, outputs (JSON)")
    add_server_options(show)
    show.add_argument("job_id")
    show.set_defaults(handler=_show)
    download = actions.add_parser("download", help="write a finished job's output files into a folder")
    add_server_options(download)
    download.add_argument("job_id")
    download.add_argument("--out", type=Path, required=True, help="output folder")
    download.add_argument("--name", action="append", default=None, metavar="FILE", help="only this output (repeatable)")
    download.set_defaults(handler=_download)
    cancel = actions.add_parser("cancel", help="cancel a queued or running job")
    add_server_options(cancel)
    cancel.add_argument("job_id")
    cancel.set_defaults(handler=_cancel)


def _with_client(args: argparse.Namespace, action: Any) -> int:
    from app.client import ClientError

    client = open_client(args)
    if client is None:
        return 2
    try:
        with client:
            return int(action(client))
    except ClientError as exc:
        err(f"error: {exc}")
        return 1


def _list(args: argparse.Namespace) -> int:
    def action(client: ArtimoClient) -> int:
        page = client.list_jobs(limit=args.limit, offset=args.offset, status=args.status)
        if args.json:
            out_json(page)
            return 0
        out(f"{'id':<38}{'status':<11}{'stage':<12}{'created':<22}prompt")
        for job in page["data"]:
            created = str(job["created_at"])[:19].replace("T", " ")
            out(f"{job['id']:<38}{job['status']:<11}{(job['stage'] or '-'):<12}{created:<22}{job['prompt'][:60]}")
        shown = len(page["data"])
        out(f"{shown} of {page['count']} jobs" + (f" (from {args.offset})" if args.offset else ""))
        return 0

    return _with_client(args, action)


def _show(args: argparse.Namespace) -> int:
    def action(client: ArtimoClient) -> int:
        out_json(client.get(args.job_id))
        return 0

    return _with_client(args, action)


def _download(args: argparse.Namespace) -> int:
    def action(client: ArtimoClient) -> int:
        job = client.get(args.job_id)
        if not job["artifacts"]:
            err(f"job {args.job_id} is {job['status']} and has no outputs yet")
            return 1
        for path in client.download(args.job_id, args.out, names=args.name):
            out(str(path))
        return 0

    return _with_client(args, action)


def _cancel(args: argparse.Namespace) -> int:
    def action(client: ArtimoClient) -> int:
        job = client.cancel(args.job_id)
        state = "cancelled" if job["status"] == "cancelled" else "cancellation requested (it stops inside its current stage)"
        out(f"job {job['id']}: {state}")
        return 0

    return _with_client(args, action)
