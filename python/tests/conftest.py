import os
import pathlib

import pytest

SOURCE = pathlib.Path(os.environ.get("GDPN_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))


@pytest.fixture
def source():
    """The repository root."""
    return SOURCE


@pytest.fixture
def write_model(tmp_path):
    """Writes model text to a file in a fresh folder and returns its path."""
    def write(text, name="m.gdpn.yaml"):
        path = tmp_path / name
        path.write_text(text)
        return str(path)
    return write
