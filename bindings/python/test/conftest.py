"""Shared fixtures of the Python tests: paths (from the environment ctest sets) and the transition oracle."""

import fcntl
import os

import pytest

SOURCE_DIR = os.environ.get("CAIRN_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", "..", ".."))
BINARY_DIR = os.environ.get("CAIRN_BINARY_DIR", os.path.join(SOURCE_DIR, "build"))
SHARED_DIR = os.environ.get("CAIRN_SHARED_DIR", os.path.join(SOURCE_DIR, "..", "shared"))


def source_path(*parts):
    return os.path.join(SOURCE_DIR, *parts)


def humanoid_walking_yaml():
    return source_path("data", "robots", "cairn_humanoid_walking.yaml")


@pytest.fixture(scope="session")
def walking_model():
    import cairn.planning as planning

    return planning.WalkingModel.Load(humanoid_walking_yaml())


@pytest.fixture(scope="session")
def oracle(walking_model):
    """The humanoid's E_COM + heat oracle, shared with the C++ tests' cache (built once, under a lock)."""
    import cairn.planning as planning

    folder = os.path.join(BINARY_DIR, "test-oracle-cache")
    os.makedirs(folder, exist_ok=True)
    path = os.path.join(folder, walking_model.name() + "-ecom_heat.oracle")
    objective = planning.WalkingObjective.kComWorkPlusHeat
    with open(path + ".lock", "a+") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        table, _ = planning.TransitionOracle.LoadOrBuild(
            path, walking_model, objective, planning.OracleGrid.Default(walking_model))
    return table
