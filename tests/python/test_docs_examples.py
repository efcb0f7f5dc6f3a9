"""Every ```python example of docs/python.md runs, from the repository's root (its scene paths)."""
import os
import pathlib
import re

import pytest

DOC = pathlib.Path(__file__).resolve().parents[2] / "docs" / "python.md"
EXAMPLES = re.findall(r"```python\n(.*?)```", DOC.read_text(), re.S)


def test_the_guide_has_examples():
    assert len(EXAMPLES) >= 4


@pytest.mark.parametrize("index", range(len(EXAMPLES)))
def test_example_runs(index, monkeypatch, capsys):
    monkeypatch.chdir(DOC.parents[1])
    exec(compile(EXAMPLES[index], f"docs/python.md example {index + 1}", "exec"),
         {"__name__": "__main__"})
    assert capsys.readouterr().out  # every example prints what it shows
