"""The Python examples of the documents run as written: the first ```python
block of docs/python.md and of README.md's "From Python" section print the
```text block that follows them, compared line by line (numbers to the
digits shown)."""
import contextlib
import io
import os
import pathlib
import re

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]


def example_and_output(doc: pathlib.Path):
    text = doc.read_text()
    code = re.search(r"```python\n(.*?)```", text, re.S)
    shown = re.search(r"```python\n.*?```.*?```text\n(.*?)```", text, re.S)
    assert code and shown, f"{doc}: a python block followed by a text block"
    return code.group(1), shown.group(1).splitlines()


@pytest.mark.parametrize("doc", ["docs/python.md", "README.md"])
def test_document_example_prints_what_it_shows(doc):
    code, shown = example_and_output(ROOT / doc)
    out = io.StringIO()
    cwd = os.getcwd()
    os.chdir(ROOT)
    try:
        with contextlib.redirect_stdout(out):
            exec(compile(code, doc, "exec"), {})
    finally:
        os.chdir(cwd)
    printed = out.getvalue().splitlines()
    assert len(printed) == len(shown), (printed, shown)
    for got, want in zip(printed, shown):
        # an estimate (after ±) varies with the machine's rounding: its
        # exponent and first digit are compared, the value in full
        if "±" in want:
            gv, ge = got.split("±")
            wv, we = want.split("±")
            assert gv == wv
            assert float(ge) <= 10 * float(we) and float(we) <= 10 * float(ge)
        else:
            assert got == want
