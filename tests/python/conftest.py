import os
import pathlib

import pytest

EXAMPLES = pathlib.Path(os.environ.get("BEMCONTACT_EXAMPLES", pathlib.Path(__file__).parents[2] / "examples"))
BINARY = os.environ.get("BEMCONTACT_BINARY", str(pathlib.Path(__file__).parents[2] / "build" / "bemcontact"))


@pytest.fixture
def examples():
    return EXAMPLES


@pytest.fixture
def binary():
    return BINARY
