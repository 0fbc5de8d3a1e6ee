"""docs/python.md's code blocks, run in order in one namespace from the source tree, so that the
walk-through stays true."""
import os
import re
from pathlib import Path

SOURCE = Path(os.environ.get("RODSHAPE_SOURCE_DIR", Path(__file__).resolve().parents[2])).resolve()


def test_the_python_walkthrough_runs(tmp_path, monkeypatch, capsys):
    text = (SOURCE / "docs" / "python.md").read_text()
    blocks = re.findall(r"```python\n(.*?)```", text, re.S)
    assert len(blocks) >= 8
    # Run where examples/ resolves, but write out/ into the test's own folder.
    (tmp_path / "examples").symlink_to(SOURCE / "examples")
    (tmp_path / "out").mkdir()
    monkeypatch.chdir(tmp_path)
    namespace = {}
    for block in blocks:
        exec(compile(block, "docs/python.md", "exec"), namespace)
    printed = capsys.readouterr().out
    assert "complete plan, 7 steps" in printed
    assert (tmp_path / "out" / "python_walkthrough" / "plan.json").exists()
    assert (tmp_path / "out" / "python_walkthrough" / "joints.png").stat().st_size > 1000
