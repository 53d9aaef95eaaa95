"""The kit as a user installs it: the sdist is built from this tree, the wheel
from the sdist (so the sdist is shown to carry everything), the wheel is
installed into a new virtual environment outside the checkout by the install
step of docs/ci/osdk-conformance.yml (the way an SDK's CI installs it), and
the README's user flows run from an empty directory. Nothing of the checkout
is on the path, and nothing is written into the installed package.

Every package pip installs here, the build backend included, comes from a
wheelhouse of the pinned versions (constraints.txt) that is downloaded once:
each resolution against the index costs pip seconds of CPU, and the CI
recipe's install, which names no constraints, gets the pinned versions too.
"""
from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
import tomllib
import zipfile
from pathlib import Path

import pytest
import yaml

from osdk_conformance.core.paths import ROOT
from osdk_conformance.reference.worked_examples import WORKED_FRAMES

pytestmark = pytest.mark.slow

CONSTRAINTS = ROOT / "constraints.txt"
WORKFLOW = ROOT / "docs/ci/osdk-conformance.yml"


def run(argv: list, cwd: Path, env: dict | None = None, timeout: float = 600) -> subprocess.CompletedProcess[str]:
    return subprocess.run([str(a) for a in argv], cwd=cwd, env=env, capture_output=True, text=True,
                          timeout=timeout, stdin=subprocess.DEVNULL)


def ok(proc: subprocess.CompletedProcess[str]) -> str:
    assert proc.returncode == 0, f"exit {proc.returncode}\n{proc.stdout[-3000:]}\n{proc.stderr[-3000:]}"
    return proc.stdout


def workflow_steps() -> dict:
    workflow = yaml.safe_load(WORKFLOW.read_text())
    return {s.get("id"): s for s in workflow["jobs"]["conformance"]["steps"]}


@pytest.fixture(scope="module")
def wheelhouse(tmp_path_factory: pytest.TempPathFactory) -> dict[str, str]:
    """pip's settings (environment variables, so that they also reach the pip
    that `build` runs and the one in the CI recipe) that install from the
    wheelhouse only: the kit's dependencies and the build backend of the kit
    and of osdk-kaitai, at the versions of constraints.txt."""
    base = tmp_path_factory.mktemp("wheelhouse")
    kit = tomllib.loads((ROOT / "pyproject.toml").read_text())
    library = tomllib.loads((ROOT / "generated/python/pyproject.toml").read_text())
    wanted = {*kit["build-system"]["requires"], *kit["project"]["dependencies"],
              *library["build-system"]["requires"]}
    ok(run([sys.executable, "-m", "pip", "download", "--quiet", "--disable-pip-version-check", "--dest", base,
            "-c", CONSTRAINTS, *sorted(wanted)], cwd=base))
    return {"PIP_NO_INDEX": "1", "PIP_FIND_LINKS": str(base)}


@pytest.fixture(scope="module")
def wheel(wheelhouse: dict[str, str], tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The wheel, built from the sdist."""
    base = tmp_path_factory.mktemp("build")
    dist = base / "dist"
    ok(run([sys.executable, "-m", "build", "--outdir", dist, ROOT], cwd=base, env={**os.environ, **wheelhouse}))
    wheels = sorted(dist.glob("*.whl"))
    assert len(wheels) == 1 and len(list(dist.glob("*.tar.gz"))) == 1
    return wheels[0]


@pytest.fixture(scope="module")
def ci_kit_step(wheel: Path, wheelhouse: dict[str, str],
                tmp_path_factory: pytest.TempPathFactory) -> tuple[dict[str, str], dict[str, Path]]:
    """The step of docs/ci/osdk-conformance.yml that installs the kit, run as
    Actions would: (the job's environment after it, the runner's files).
    It makes the new virtual environment every test of the installed kit
    uses, so the recipe's install is the one those tests judge."""
    base = tmp_path_factory.mktemp("runner")
    actions = {"RUNNER_TEMP": base / "temp", "GITHUB_PATH": base / "path",
               "GITHUB_STEP_SUMMARY": base / "summary.md"}
    actions["RUNNER_TEMP"].mkdir()
    # actions/setup-python's `python`: the interpreter of this run, not
    # whichever one the machine has first on its PATH
    setup_python = base / "setup-python"
    setup_python.mkdir()
    (setup_python / "python").symlink_to(Path(sys.executable).resolve())
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "VIRTUAL_ENV", "OSDK_SEED")}
    # no virtual environment (the checkout's included) is on the job's PATH
    env["PATH"] = os.pathsep.join([str(setup_python), *(p for p in env["PATH"].split(os.pathsep)
                                                        if "venv" not in p)])
    env["XDG_CACHE_HOME"] = str(base / "cache")
    ok(run(["bash", "-e", "-c", workflow_steps()["kit"]["run"]], cwd=base,
           env={**env, **{k: str(v) for k, v in actions.items()}, **wheelhouse, "OSDKC_WHEEL": str(wheel)}))
    env["PATH"] = os.pathsep.join([*actions["GITHUB_PATH"].read_text().split(), env["PATH"]])
    return env, actions


@pytest.fixture(scope="module")
def installed(ci_kit_step, tmp_path_factory: pytest.TempPathFactory) -> tuple[Path, dict[str, str], Path]:
    """(the installed osdkc, its environment, an empty working directory)."""
    env, actions = ci_kit_step
    kit = Path(actions["GITHUB_PATH"].read_text().split()[0])
    return kit / "osdkc", env, tmp_path_factory.mktemp("work")


def osdkc(installed, *argv: str, timeout: float = 600) -> subprocess.CompletedProcess[str]:
    exe, env, work = installed
    return run([exe, *argv], cwd=work, env=env, timeout=timeout)


def test_the_wheel_installs_only_the_kit_package(wheel: Path) -> None:
    # Anything else at the top of site-packages would be another distribution's
    # to overwrite or remove: osdk_kaitai is the name of the generated library.
    with zipfile.ZipFile(wheel) as whl:
        names = whl.namelist()
        info = next(n.split("/")[0] for n in names if n.split("/")[0].endswith(".dist-info"))
        assert {n.split("/")[0] for n in names} == {"osdk_conformance", info}
        assert whl.read(f"{info}/top_level.txt").decode().split() == ["osdk_conformance"]
        # the kit's Kaitai parsers are generated/python's files under the kit's name, not a copy of their own
        source = ROOT / "generated/python/osdk_kaitai"
        carried = {n.rsplit("/", 1)[1]: whl.read(n) for n in names if n.startswith("osdk_conformance/_kaitai/")}
        assert carried == {p.name: p.read_bytes() for p in source.glob("*.py")}


def test_it_runs_from_the_installed_package(installed) -> None:
    out = ok(osdkc(installed, "--version"))
    assert "installed at" in out and str(ROOT) not in out
    assert "decoder: native (" in out  # compiled at install: this machine has gcc


def test_the_installed_accelerator_conforms(installed) -> None:
    out = ok(osdkc(installed, "run", "--impl", "accel", "--profile", "m100-fw2.3", "--quiet"))
    assert "CONFORMS for decode_frame, decode_payload, decode_stream" in out


def test_without_a_compiler_the_install_goes_on_in_pure_python(wheel, wheelhouse, tmp_path) -> None:
    sdist = next(wheel.parent.glob("*.tar.gz"))
    venv = tmp_path / "venv"
    # without a pip of its own, which ensurepip takes seconds to install: pip --python installs
    # into it, running in the venv's interpreter as the venv's own pip would
    ok(run([sys.executable, "-m", "venv", "--without-pip", venv], cwd=tmp_path))
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "VIRTUAL_ENV")}
    env["CC"] = "false"  # the C compiler fails, as a missing one does
    # --no-cache-dir: this build is the test's own, neither taken from pip's cache nor left in it
    ok(run([sys.executable, "-m", "pip", "--python", venv / "bin/python", "install", "--quiet",
            "--disable-pip-version-check", "--no-cache-dir", "-c", CONSTRAINTS, sdist],
           cwd=tmp_path, env={**env, **wheelhouse}))
    env["XDG_CACHE_HOME"] = str(tmp_path / "cache")
    out = ok(run([venv / "bin/osdkc", "--version"], cwd=tmp_path, env=env))
    assert "decoder: pure Python (no native decoder" in out
    wf = next(w for w in WORKED_FRAMES if w.profile == "a3-fw3.1" and "battery" in w.name)
    ok(run([venv / "bin/osdkc", "decode", "--profile", wf.profile, "--hex", wf.hex], cwd=tmp_path, env=env))
    env["OSDKC_ACCEL"] = "1"
    proc = run([venv / "bin/osdkc", "decode", "--profile", wf.profile, "--hex", wf.hex], cwd=tmp_path, env=env)
    assert proc.returncode == 2 and "native decoder is not installed" in proc.stderr
    proc = run([venv / "bin/osdkc", "run", "--impl", "all", "--filter", "worked", "--quiet"],
               cwd=tmp_path, env={**env, "OSDKC_ACCEL": ""})
    assert "not run: accel: the native decoder was not compiled" in proc.stdout


def test_decode(installed) -> None:
    wf = next(w for w in WORKED_FRAMES if w.profile == "a3-fw3.1" and "battery" in w.name)
    events = [json.loads(line) for line in ok(osdkc(installed, "decode", "--profile", wf.profile,
                                                    "--hex", wf.hex)).splitlines()]
    assert [e["kind"] for e in events] == ["frame"]
    assert events[0]["frame"]["data"]["value"]["body"]["data"]["battery"] == 87


def test_spec_check_says_what_it_could_not_check(installed) -> None:
    out = ok(osdkc(installed, "spec", "check"))
    assert "skip  ksy" in out and "needs a checkout" in out
    assert "ok    rules" in out and "ok    errata" in out


def test_vectors_check_and_coverage(installed) -> None:
    assert "OK" in ok(osdkc(installed, "vectors", "check", "--no-spec")).upper()
    ok(osdkc(installed, "vectors", "coverage"))


@pytest.mark.parametrize("impl", ["construct", "kaitai-python"])
def test_run_a_bundled_python_implementation(installed, impl: str) -> None:
    out = ok(osdkc(installed, "run", "--impl", impl, "--profile", "a3-fw3.1", "--filter", "worked",
                   "--quiet"))
    assert "CONFORMS" in out


def test_installing_and_removing_the_generated_library_leaves_the_kit_alone(installed, wheelhouse,
                                                                           tmp_path: Path) -> None:
    exe, env, work = installed
    python, pip = exe.parent / "python", [exe.parent / "pip", "--disable-pip-version-check", "--quiet"]
    src = tmp_path / "osdk-kaitai"  # a copy: building writes into the source tree
    shutil.copytree(ROOT / "generated/python", src, ignore=shutil.ignore_patterns("__pycache__", "build"))
    pip_env = {**env, **wheelhouse}  # the build backend comes from the wheelhouse
    ok(run([*pip, "install", "--no-deps", src], cwd=work, env=pip_env))
    where = ok(run([python, "-c", "import osdk_kaitai, osdk_conformance._kaitai as k; "
                                  "print(osdk_kaitai.__file__); print(k.__file__)"], cwd=work, env=env)).split()
    assert Path(where[0]).parent.name == "osdk_kaitai" and Path(where[1]).parent.name == "_kaitai"
    ok(run([*pip, "uninstall", "--yes", "osdk-kaitai"], cwd=work, env=pip_env))
    gone = run([python, "-c", "import osdk_kaitai"], cwd=work, env=env)
    assert gone.returncode == 1 and "No module named 'osdk_kaitai'" in gone.stderr
    ok(run([python, "-c", "import osdk_conformance.api"], cwd=work, env=env))
    out = ok(osdkc(installed, "run", "--impl", "kaitai-python", "--profile", "a3-fw3.1", "--filter", "worked",
                   "--quiet"))
    assert "CONFORMS" in out


def test_a_testee_in_another_language_needs_the_checkout(installed) -> None:
    proc = osdkc(installed, "run", "--impl", "c")
    assert proc.returncode == 2 and "needs a checkout" in proc.stderr and "Traceback" not in proc.stderr


def test_the_sdk_testee_sources_are_in_the_package(installed) -> None:
    # osdkc sdk build compiles them against the user's DJI checkout
    exe, env, work = installed
    check = ("from osdk_conformance.sdk import testee_build as t\n"
             "from osdk_conformance.sdk.families import core, protocol\n"
             "need = [*t.KIT_SOURCES, core.ADAPTER_DIR / 'adapter.cpp', protocol.ADAPTER_DIR / 'adapter.cpp']\n"
             "print(sorted(str(p) for p in need if not p.is_file()))")
    assert ok(run([exe.parent / "python", "-c", check], cwd=work, env=env)).strip() == "[]"
    (work / "empty").mkdir(exist_ok=True)
    proc = osdkc(installed, "sdk", "build", "--osdk", str(work / "empty"))
    assert proc.returncode == 2 and "not a DJI Onboard-SDK checkout" in proc.stderr and "Traceback" not in proc.stderr


def test_the_wireshark_dissector_installs_from_the_package(installed) -> None:
    target = installed[2] / "plugins"
    out = ok(osdkc(installed, "wireshark", "install", "--dir", str(target)))
    assert (target / "osdk.lua").read_bytes() == (ROOT / "generated" / "wireshark" / "osdk.lua").read_bytes()
    assert str(target) in out


def test_selftest_one_mutant(installed) -> None:
    out = ok(osdkc(installed, "selftest", "--mutant", "crc16_init_ffff", "--no-baseline"))
    assert "killed" in out


def test_fuzz(installed) -> None:
    ok(osdkc(installed, "fuzz", "--impl", "construct", "--impl", "kaitai-python", "--max-examples", "50",
             "--seed", "1"))


def test_sim(installed) -> None:
    proc = osdkc(installed, "sim", "--profile", "a3-fw3.1", "--exit-after", "0.3", timeout=60)
    ok(proc)


def test_soak_streams_from_the_simulator_through_the_receiver(installed) -> None:
    numbers = json.loads(ok(osdkc(installed, "soak", "--duration", "2", "--hz", "10", "--json", timeout=120)))
    assert numbers["profile"] == "a3-fw3.1"


def test_the_python_api_from_the_installed_package(installed) -> None:
    exe, env, work = installed
    script = ("from osdk_conformance import api\n"
              "run = api.run_conformance(impl='construct', filter='worked')\n"
              "print(run.conforms, len(run.results))\n")
    out = ok(run([exe.parent / "python", "-c", script], cwd=work, env=env))
    conforms, cases = out.split()
    assert conforms == "True" and int(cases) > 0


def test_nothing_was_written_into_the_package(installed) -> None:
    exe, env, _ = installed
    site = Path(ok(run([exe.parent / "python", "-c", "import osdk_conformance, pathlib; "
                                                      "print(pathlib.Path(osdk_conformance.__file__).parent)"],
                       cwd=installed[2], env=env)).strip())
    written = [p for p in (site / "_data").rglob("*") if p.is_dir() and p.name in ("reports", ".cache")]
    assert written == []


def test_the_ci_recipe_runs(ci_kit_step, tmp_path: Path) -> None:
    """The steps of docs/ci/osdk-conformance.yml that are the kit's (install it,
    replay the vectors), run as Actions would, with the bundled Construct
    testee standing in for an SDK's; the build step is the SDK's own. The
    install step runs in the ci_kit_step fixture: the other tests of the
    installed kit use the venv it makes."""
    steps = workflow_steps()
    sdk = tmp_path / "sdk"
    (sdk / "conformance").mkdir(parents=True)
    (sdk / "conformance/osdk-failures.txt").write_text("# no known failure\n")
    env, actions = ci_kit_step
    env = {**env, **{k: str(v) for k, v in actions.items()}}
    kit = Path(actions["GITHUB_PATH"].read_text().split()[0])
    data = ok(run([kit / "python", "-c", "from osdk_conformance.core.paths import ROOT; print(ROOT)"],
                  cwd=sdk, env=env)).strip()
    testee = f"{kit / 'python'} {data}/conformance/testees/construct_testee.py"
    out = ok(run(["bash", "-e", "-c", steps["conformance"]["run"]], cwd=sdk,
                 env={**env, "OSDKC_TESTEE": testee,
                      # the recipe's wiring is under test here; the Construct testee's full
                      # replay is tests/test_runner.py's
                      "OSDKC_RUN_ARGS": "--profile a3-fw3.1 --filter worked"}))
    assert "CONFORMS" in out
    reports = sdk / "osdk-reports"
    assert {p.name for p in reports.iterdir()} >= {"conformance.xml", "conformance.html", "summary.json", "run.txt"}
    assert json.loads((reports / "summary.json").read_text())["conforms"] is True
    assert "OPEN protocol conformance" in actions["GITHUB_STEP_SUMMARY"].read_text()
