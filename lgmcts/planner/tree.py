"""Search-tree nodes. Nodes hold an immutable domain state; only their
visit statistics change during the search."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Generic, TypeVar

__all__ = ["Node"]

S = TypeVar("S")
A = TypeVar("A")


@dataclass(eq=False)
class Node(Generic[S, A]):
    """One search-tree node.

    ``action`` is the action that led here from ``parent`` (``None`` for the
    root and for a choice committed without an action, a goal object left
    where it already stood); ``attempts`` counts expansion tries per choice;
    ``dead`` marks a node with nothing left to explore below it.
    """

    state: S
    parent: Node[S, A] | None = None
    action: A | None = None
    depth: int = 0
    n_actions: int = 0
    reward: float = 0.0
    visits: int = 0
    value: float = 0.0
    children: list[Node[S, A]] = field(default_factory=list)
    attempts: dict[int, int] = field(default_factory=dict)
    dead: bool = False

    def path(self) -> list[A]:
        """Actions from the root to this node."""
        out: list[A] = []
        node: Node[S, A] | None = self
        while node is not None:
            if node.action is not None:
                out.append(node.action)
            node = node.parent
        return out[::-1]

    def trace(self) -> list[S]:
        """States along :meth:`path`: the root's, then the one after each action."""
        out: list[S] = []
        node: Node[S, A] | None = self
        while node is not None:
            if node.action is not None or node.parent is None:
                out.append(node.state)
            node = node.parent
        return out[::-1]
