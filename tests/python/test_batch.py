"""docs/batch.md's recipe: 20 validations on a LocalCluster of 2 worker processes give the documents
of the same validations in series. The recipe's code is taken from the page, so that it stays
true."""
import logging
import os
import re
from pathlib import Path

import pytest

distributed = pytest.importorskip(
    "dask.distributed",
    reason="dask.distributed is missing (Debian: python3-distributed, which "
    "scripts/install-deps.sh installs): docs/batch.md's recipe is not tested",
)

# Tornado, under Dask, warns of its own deprecated calls.
pytestmark = pytest.mark.filterwarnings("ignore::DeprecationWarning")

SOURCE = Path(os.environ.get("RODSHAPE_SOURCE_DIR", Path(__file__).resolve().parents[2])).resolve()

# A small plan task (the gentle bend of tests/cli/test_cli_plan.cpp: 51 nodes, two steps), so that
# 20 validations take a few seconds.
TASK = """rod:
  length: 0.29
  nodes: 51
  section: {shape: rectangle, width: 0.02, height: 0.02}
  material: {young_modulus: 3.2e6, poisson_ratio: 0.5, density: 1392}
  stiffness: {EIx: 0.04, EIy: 0.04, GJ: 0.028}
target:
  points:
    - [0.003, 0.000, 0.057]
    - [0.013, 0.000, 0.114]
    - [0.030, 0.000, 0.169]
    - [0.052, 0.000, 0.223]
    - [0.081, 0.000, 0.273]
trajectory:
  steps: 2
"""


def recipe():
    """The functions of docs/batch.md's code block (run without its __main__ part)."""
    text = (SOURCE / "docs" / "batch.md").read_text()
    (block,) = re.findall(r"```python\n(.*?)```", text, re.S)
    namespace = {"__name__": "batch_recipe"}
    exec(compile(block, "docs/batch.md", "exec"), namespace)
    return namespace


def test_twenty_validations_on_a_two_worker_local_cluster_equal_the_serial_ones(tmp_path):
    task = tmp_path / "bend.yaml"
    task.write_text(TASK)
    paths = [str(task)] * 20
    seeds = list(range(1, 21))
    functions = recipe()
    serial = [functions["validate_one"](p, s) for p, s in zip(paths, seeds)]
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None, silence_logs=logging.ERROR) as cluster:
        with distributed.Client(cluster) as client:
            assert len(client.scheduler_info()["workers"]) == 2
            batch = functions["validate_all"](client, paths, seeds)
    assert batch == serial
    assert len(set(serial)) == 20  # each seed its own noise: 20 different documents
    assert all('"status": "complete"' in document for document in serial)
