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

    #: Longest message (characters); a longer one (an echoed 100 KB
    #: instruction, say) is cut, with its full length noted.
    MAX_LENGTH = 500

    def __init__(self, message: str) -> None:
        line = " ".join(str(message).split())
        if len(line) > self.MAX_LENGTH:
            line = f"{line[: self.MAX_LENGTH]}... ({len(line)} characters)"
        super().__init__(line)
