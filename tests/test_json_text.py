"""derive.publishing.json_text writes the text json.dumps(indent=2, ensure_ascii=False) writes (key.json's)."""
import json

from hypothesis import given, strategies as st

from derive.publishing import json_text

SCALARS = st.none() | st.booleans() | st.integers() | st.floats(allow_nan=False) | st.text()
VALUES = st.recursive(SCALARS, lambda inner: st.lists(inner, max_size=4) | st.dictionaries(st.text(), inner, max_size=4),
                      max_leaves=30)


@given(VALUES)
def test_the_text_is_jsons(value):
    assert json_text.dumps(value) == json.dumps(value, indent=2, ensure_ascii=False)
