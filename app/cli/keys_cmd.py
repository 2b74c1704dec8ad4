"""``artimo keys create --name NAME`` / ``artimo keys list``: API keys of the service."""

from __future__ import annotations

import argparse
from typing import TYPE_CHECKING

from app.cli.output import err, out

if TYPE_CHECKING:
    from sqlalchemy.orm import Session, sessionmaker


def register(commands: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    keys = commands.add_parser("keys", help="manage API keys of the service (database from $DATABASE_URL or the embedded default)")
    actions = keys.add_subparsers(dest="keys_command", required=True, metavar="ACTION")
    create = actions.add_parser("create", help="create a client and print its new key (shown once)")
    create.add_argument("--name", required=True, help="who the key is for")
    create.add_argument("--rate-limit", type=int, default=None, help="requests per minute (default: $RATE_LIMIT_PER_MINUTE)")
    create.set_defaults(handler=_create)
    listing = actions.add_parser("list", help="list clients (key prefixes only)")
    listing.set_defaults(handler=_list)
    disable = actions.add_parser("disable", help="disable the client(s) with this key prefix")
    disable.add_argument("prefix", help="key prefix as shown by 'artimo keys list'")
    disable.set_defaults(handler=_disable)


def _sessions() -> sessionmaker[Session]:
    from app.core.config import get_settings
    from app.db.migrate import upgrade
    from app.db.session import session_factory

    settings = get_settings()
    if settings.database_url is None:  # embedded: make sure the schema exists
        upgrade(settings.sqlalchemy_url)
    return session_factory(settings.sqlalchemy_url)


def _where() -> str:
    """Which service a key belongs to: its database (and the data folder of the embedded one)."""
    from app.core.config import get_settings

    settings = get_settings()
    if settings.database_url is None:
        return f"the embedded database {settings.database_shown} (ARTIMO_DATA_DIR={settings.data_dir})"
    return f"the database {settings.database_shown} ($DATABASE_URL)"


def _create(args: argparse.Namespace) -> int:
    from app.crud.clients import create_api_client

    if args.rate_limit is not None and args.rate_limit <= 0:
        err("--rate-limit must be positive")
        return 2
    with _sessions()() as session:
        client, key = create_api_client(session, name=args.name, rate_limit_per_minute=args.rate_limit)
    err(f"created client {client.name!r} ({client.id}) in {_where()}: a server using it accepts the key; it is shown once:")
    out(key)
    return 0


def _list(_args: argparse.Namespace) -> int:
    from app.crud.clients import list_api_clients

    with _sessions()() as session:
        clients = list_api_clients(session)
    out(f"{'prefix':<14}{'name':<30}{'created':<22}{'limit/min':<11}state")
    for client in clients:
        limit = "-" if client.rate_limit_per_minute is None else str(client.rate_limit_per_minute)
        state = "disabled" if client.disabled else "active"
        out(f"{client.key_prefix:<14}{client.name[:29]:<30}{client.created_at:%Y-%m-%d %H:%M:%S}   {limit:<11}{state}")
    return 0


def _disable(args: argparse.Namespace) -> int:
    from app.crud.clients import list_api_clients, set_client_disabled

    with _sessions()() as session:
        matches = [c for c in list_api_clients(session) if c.key_prefix.startswith(args.prefix)]
        if len(matches) != 1:
            err(f"{len(matches)} clients match {args.prefix!r}; give a longer prefix")
            return 1
        set_client_disabled(session, client=matches[0], disabled=True)
    out(f"disabled {matches[0].name!r}")
    return 0
