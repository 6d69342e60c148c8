"""The validation table's topics of group 'b' computed now equal the shipped rows (tests/validation_fresh.py)."""

import pytest
from validation_fresh import GROUPS, check_topic


@pytest.mark.parametrize("topic", GROUPS["b"])
def test_the_topic_computed_now_equals_the_shipped_rows(topic):
    check_topic(topic)
