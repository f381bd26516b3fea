"""``python -m lgmcts.service [OPTIONS]``: the ``serve`` command on its own.

The same options as ``lgmcts serve``; useful where only the service is wanted
(containers, process supervisors) since it loads no other command-line plugin.
"""

import typer

from ..cli_util import run_app
from .cli import register

app = typer.Typer(add_completion=False, pretty_exceptions_enable=False)
register(app)

if __name__ == "__main__":
    run_app(app, prog_name="python -m lgmcts.service")
