"""The examples of docs/python.md marked `<!-- runs in test_docs.py -->` run as written."""

import pathlib
import re

import pytest

DOCS = pathlib.Path(__file__).resolve().parents[3] / "docs" / "python.md"
BLOCKS = re.findall(r"<!-- runs in test_docs.py -->\n```python\n(.*?)```", DOCS.read_text(), flags=re.S)


def test_the_docs_have_examples():
    assert len(BLOCKS) >= 7


@pytest.mark.parametrize("block", BLOCKS, ids=[f"example {k}" for k in range(len(BLOCKS))])
def test_docs_example_runs(block):
    exec(compile(block, str(DOCS), "exec"), {})
