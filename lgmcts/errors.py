"""Exception types shared by every layer.

Expected failures of planning are values (``Plan(solved=False)``); only bad
input raises, always with a one-line message that names the problem.
"""

from __future__ import annotations


class InputError(ValueError):
    """Bad input: a malformed file, an unknown id, an impossible goal.

    The message is a single line meant for a person; the CLI prints it and
    exits with status 2, the service answers 422 with it.
    """

    def __init__(self, message: str) -> None:
        super().__init__(" ".join(str(message).split()))
