"""The Python code of the README and docs/python.md runs as written, from the checkout's root."""
import os
import re
import runpy

import pytest


def python_blocks(path):
    with open(path) as handle:
        return re.findall(r"```python\n(.*?)```", handle.read(), re.S)


@pytest.mark.parametrize("page", ["README.md", "docs/python.md"])
def test_the_pages_code_runs(root, page, monkeypatch, tmp_path, capsys):
    blocks = python_blocks(os.path.join(root, page))
    assert blocks, page + " has no python block"
    monkeypatch.chdir(root)
    for number, block in enumerate(blocks):
        script = tmp_path / ("block%d.py" % number)
        script.write_text(block)
        runpy.run_path(str(script), run_name="__main__")
    printed = capsys.readouterr().out
    assert "(8, 3)" in printed or "(12, 3)" in printed
