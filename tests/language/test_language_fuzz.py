"""Any word salad either parses into goals valid for the scene or is refused in one line."""

from __future__ import annotations

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from lgmcts.errors import InputError
from lgmcts.language import parse

pytestmark = pytest.mark.slow

WORDS = (
    "put place stack line up arrange all the a one two three other another except but not red blue green yellow "
    "white purple polka dot and ; then while also . block blocks bowl bottle mug mugs cup phone letter A in a row "
    "circle ring square rectangle tower on top of left right front behind of to it them object 7 3 , whose color "
    "is same as every both giraffe spiral next from bottom"
).split()


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(st.lists(st.sampled_from(WORDS), min_size=1, max_size=14))
def test_parse_never_crashes_and_goals_refer_to_the_scene(tabletop, matcher, words):
    text = " ".join(words)
    try:
        spec = parse(tabletop, text)
    except InputError as exc:
        assert str(exc) and "\n" not in str(exc)
        return
    spec.check_against(tabletop)
    ids = {o.id for o in tabletop.objects}
    for g in spec.goals:
        assert set(g.objects) <= ids
