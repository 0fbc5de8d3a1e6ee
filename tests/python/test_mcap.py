"""Plan.write_mcap (issue 49): plan.mcap's content from Python, as `rodshape plan --mcap` writes it
(the decoders' test, io.mcap_decoders, reads those files message by message)."""
import os
import struct
from pathlib import Path

import pytest

import rodshape

SOURCE = Path(os.environ.get("RODSHAPE_SOURCE_DIR", Path(__file__).resolve().parents[2]))
MAGIC = b"\x89MCAP0\r\n"


def header_of(data):
    """The Header record's profile and library (opcode 1, uint64 length, two uint32 strings)."""
    assert data[8] == 1
    size = struct.unpack_from("<I", data, 17)[0]
    profile = data[21:21 + size].decode()
    library_size = struct.unpack_from("<I", data, 21 + size)[0]
    library = data[25 + size:25 + size + library_size].decode()
    return profile, library


@pytest.fixture(scope="module")
def plan():
    return rodshape.plan(rodshape.load_task(str(SOURCE / "examples" / "plan_c_arc.yaml")))


def test_write_mcap_writes_a_whole_mcap_file_named_rodshapes(plan, tmp_path):
    for compression in ("zstd", "none"):
        path = tmp_path / f"plan_{compression}.mcap"
        plan.write_mcap(str(path), compression)
        data = path.read_bytes()
        assert data.startswith(MAGIC) and data.endswith(MAGIC)
        assert header_of(data) == ("ros2", f"rodshape {rodshape.__version__}")
        assert b"visualization_msgs/msg/MarkerArray" in data  # the schemas: never compressed
        assert (b"zstd" in data) == (compression == "zstd")
    assert (tmp_path / "plan_zstd.mcap").stat().st_size < (tmp_path / "plan_none.mcap").stat().st_size


def test_write_mcap_refuses_a_link_and_an_unknown_compression(plan, tmp_path):
    target = tmp_path / "elsewhere.mcap"
    target.write_text("not to be overwritten")
    link = tmp_path / "plan.mcap"
    link.symlink_to(target)
    with pytest.raises(rodshape.InputError, match="symbolic link"):
        plan.write_mcap(str(link))
    assert target.read_text() == "not to be overwritten"
    with pytest.raises(rodshape.InputError, match="compression"):
        plan.write_mcap(str(tmp_path / "other.mcap"), "lz4")
    assert not (tmp_path / "other.mcap").exists()
