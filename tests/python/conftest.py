import os
import pathlib

import pytest

EXAMPLES = pathlib.Path(os.environ.get("BEMCONTACT_EXAMPLES", pathlib.Path(__file__).parents[2] / "examples"))
BINARY = os.environ.get("BEMCONTACT_BINARY", str(pathlib.Path(__file__).parents[2] / "build" / "bemcontact"))


@pytest.fixture(scope="session")
def examples():
    return EXAMPLES


@pytest.fixture(scope="session")
def binary():
    return BINARY
