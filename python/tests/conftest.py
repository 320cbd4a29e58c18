import os
import pathlib

import pytest

MESHES = pathlib.Path(os.environ.get("HOOKE_MESH_DATA", pathlib.Path(__file__).resolve().parents[2] / "data" / "meshes"))


@pytest.fixture
def meshes():
    return MESHES
