"""A stack's order said as a list of roles by colour (lgmcts.language.stack_order)."""

from __future__ import annotations

import itertools

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from lgmcts.errors import InputError
from lgmcts.language.stack_order import stack_orders


@pytest.mark.parametrize(("said", "read"), [
    ("stack all 4 blocks w/ yellow on top, green under it, red under green, blue at the bottom",
     "stack all 4 blocks, from the bottom up: blue, red, green, yellow"),
    ("stack the blocks: blue at the bottom, red on blue, green on red, yellow on top",
     "stack the blocks, from the bottom up: blue, red, green, yellow"),
    ("stack the bowls, the green one on the blue one and the white one on top of the green one",
     "stack the bowls, from the bottom up: blue, green, white"),
    # said with no stack word: a sentence that is only the list, its objects' noun kept
    ("Um, the green bowl on the blue bowl, and the white bowl on top of the green bowl, so the green one's in the "
     "middle.", "Um, stack the blue bowl, the green bowl and the white bowl from the bottom up."),
    # "then" goes up from a base, or down from a top
    ("Tower: orange base, then purple, green on purple, blue to top it off.",
     "Tower, from the bottom up: orange, purple, green, blue."),
    ("stack them: yellow on top, then green, then red, blue under red",
     "stack them, from the bottom up: blue, red, green, yellow"),
    # the nouns said with the colours go with them
    ("build a tower: the red can at the bottom, the blue can on the red can, the green can on top",
     "build a tower, from the bottom up: the red can, the blue can, the green can"),
])
def test_one_order_is_said_plainly(said: str, read: str) -> None:
    assert stack_orders(said) == read


@pytest.mark.parametrize("said", [
    "Stack the cups, red on blue, blue on red.",
    "stack the blocks: red at the bottom, blue on red, blue at the bottom",
    "the green bowl on the blue bowl, and the white bowl on the green bowl, so the green one's at the bottom.",
])
def test_contradicting_roles_are_refused(said: str) -> None:
    with pytest.raises(InputError, match="contradict"):
        stack_orders(said)


@pytest.mark.parametrize("said", [
    "stack the cups: red on blue",                                  # one item: the later stages read it
    "stack the blocks, red at the bottom, blue on top",             # places only: read as before
    "Tower: orange base, then purple, then green, blue on top",     # places and "then" only: read as before
    "stack the blocks: red on blue, green on yellow",               # two orders keep both items
    "put the red block on the blue block and the green block on the red block",  # a verb of its own
])
def test_other_lists_are_left_as_said(said: str) -> None:
    assert stack_orders(said) == said


_HUES = ["red", "blue", "green", "yellow", "purple"]


@settings(max_examples=60, deadline=None)
@given(st.permutations(_HUES).map(lambda p: p[: 4]), st.randoms(use_true_random=False))
def test_any_chain_said_in_any_order_gives_its_stack(order: list[str], rnd) -> None:
    """A stack said as "X on Y" for each neighbouring pair, the items shuffled: the one order is the stack's."""
    items = [f"{a} on {b}" for b, a in itertools.pairwise(order)]
    rnd.shuffle(items)
    said = "stack the blocks: " + ", ".join(items)
    assert stack_orders(said) == "stack the blocks, from the bottom up: " + ", ".join(order)
