"""The examples in the docstrings run and give what they show."""

import doctest

import numpy as np
import pytest

import obbsat
import obbsat.testing


@pytest.mark.parametrize("module", [obbsat, obbsat.testing], ids=lambda m: m.__name__)
def test_docstring_examples(module):
    result = doctest.testmod(module, extraglobs={"np": np, "obbsat": obbsat}, verbose=False)
    assert result.attempted > 0
    assert result.failed == 0


def test_every_public_function_has_an_example():
    for name in obbsat.__all__:
        item = getattr(obbsat, name)
        if callable(item) and not isinstance(item, type):
            assert ">>> " in (item.__doc__ or ""), f"obbsat.{name} has no example"
