"""Sweeps on a cluster, on a real one: a single-node Slurm cluster on localhost (Debian's
slurm-wlm and munge, which tests/run.sh installs) started here in a temporary directory with a
generated slurm.conf, and stopped afterwards. harness/scripts/sweep_array.sbatch runs a small
configuration as a 4-task job array; `curvebench merge` joins the shards; the result equals the
same sweep on one machine apart from the measurements. If Slurm cannot start, the test fails
with the daemons' logs: it is never skipped."""
import json
import os
import pathlib
import shutil
import socket
import subprocess
import tempfile
import time

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
SBATCH_SCRIPT = ROOT / "harness" / "scripts" / "sweep_array.sbatch"
CONFIG = {"seeds": [1, 2], "algorithms": ["labeling", "crust", "nn-crust"],
          "inputs": [{"family": ["ellipse", "rose"], "epsilon": [0.2, 0.3]}]}
MEASUREMENTS = ("timing_ms", "evaluate_ms", "wall_ms", "peak_memory_kb")
TASKS = 4


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


class SlurmCluster:
    """munged, slurmctld and slurmd in the foreground, as children of the test, in `directory`."""

    def __init__(self, directory: pathlib.Path):
        self.directory = directory
        self.processes = []
        self.logs = {name: directory / f"{name}.log" for name in ("munged", "slurmctld", "slurmd")}
        self.environment = {**os.environ, "SLURM_CONF": str(directory / "slurm.conf")}

    def log_tails(self):
        return "\n".join(f"--- {path}:\n" + ("\n".join(path.read_text(errors="replace").splitlines()[-30:])
                                             if path.exists() else "(no log)") for path in self.logs.values())

    def fail(self, what):
        pytest.fail(f"Slurm: {what}\n{self.log_tails()}", pytrace=False)

    def start(self):
        for program in ("munged", "mungekey", "slurmctld", "slurmd", "sbatch", "sinfo"):
            if shutil.which(program) is None:
                pytest.fail(f"{program} not found: install the Debian packages slurm-wlm and munge (tests/run.sh does)")
        if os.geteuid() != 0:
            pytest.fail("the Slurm test starts slurmd, which runs jobs as their user and so must run as root (CI does)")
        d = self.directory
        for sub, mode in (("munge", 0o700), ("run", 0o755), ("state", 0o755), ("spool", 0o755)):
            (d / sub).mkdir()
            (d / sub).chmod(mode)
        key = d / "munge" / "munge.key"
        subprocess.run(["mungekey", "--create", f"--keyfile={key}"], check=True, capture_output=True)
        socket_path = d / "run" / "munge.socket"  # munged wants its socket's directory open to all
        self.spawn(["munged", "--foreground", f"--key-file={key}", f"--socket={socket_path}",
                    f"--pid-file={d / 'run' / 'munged.pid'}", f"--seed-file={d / 'munge' / 'seed'}",
                    f"--log-file={self.logs['munged']}"])
        self.wait_for(socket_path.exists, "munged made no socket")
        host = socket.gethostname().split(".")[0]
        (d / "slurm.conf").write_text("\n".join([
            "ClusterName=curvebench-test",
            f"SlurmctldHost={host}(127.0.0.1)",
            f"SlurmctldPort={free_port()}",
            f"SlurmdPort={free_port()}",
            "SlurmUser=root",
            "SlurmdUser=root",
            "AuthType=auth/munge",
            "CredType=cred/munge",
            f"AuthInfo=socket={socket_path}",
            f"StateSaveLocation={d / 'state'}",
            f"SlurmdSpoolDir={d / 'spool'}",
            f"SlurmctldPidFile={d / 'run' / 'slurmctld.pid'}",
            f"SlurmdPidFile={d / 'run' / 'slurmd.pid'}",
            f"SlurmctldLogFile={self.logs['slurmctld']}",
            f"SlurmdLogFile={self.logs['slurmd']}",
            "ProctrackType=proctrack/linuxproc",  # no cgroups: the test machine need not have them set up
            "TaskPlugin=task/none",
            "JobAcctGatherType=jobacct_gather/none",
            "AccountingStorageType=accounting_storage/none",
            "JobCompType=jobcomp/none",
            "SchedulerType=sched/builtin",
            "SelectType=select/cons_tres",
            "SelectTypeParameters=CR_CPU",
            "MpiDefault=none",
            "ReturnToService=2",
            f"NodeName={host} NodeAddr=127.0.0.1 CPUs={os.cpu_count()} State=UNKNOWN",
            "PartitionName=test Nodes=ALL Default=YES MaxTime=INFINITE State=UP",
        ]) + "\n")
        conf = str(d / "slurm.conf")
        self.spawn(["slurmctld", "-D", "-i", "-f", conf])
        self.spawn(["slurmd", "-D", "-f", conf, "-N", host])  # the node by its configured name

        def node_idle():
            states = subprocess.run(["sinfo", "--noheader", "--format=%T"], env=self.environment, capture_output=True,
                                    text=True).stdout.split()
            return states == ["idle"]

        self.wait_for(node_idle, "the node did not become idle")

    def spawn(self, command):
        process = subprocess.Popen(command, env=self.environment, stdout=subprocess.DEVNULL, stderr=subprocess.STDOUT)
        self.processes.append(process)

    def wait_for(self, condition, what, seconds=60):
        deadline = time.monotonic() + seconds
        while not condition():
            exited = [p.args[0] for p in self.processes if p.poll() is not None]
            if exited:
                self.fail(f"{', '.join(exited)} exited while starting ({what})")
            if time.monotonic() > deadline:
                self.fail(f"{what} within {seconds} s")
            time.sleep(0.5)

    def stop(self):
        for process in reversed(self.processes):  # slurmd, slurmctld, then munged
            process.terminate()
            try:
                process.wait(timeout=20)
            except subprocess.TimeoutExpired:
                process.kill()
                process.wait()


@pytest.fixture(scope="module")
def slurm_cluster():
    directory = pathlib.Path(tempfile.mkdtemp(prefix="curvebench-slurm-"))  # not under pytest's 0700 tmp: munged checks
    directory.chmod(0o755)
    cluster = SlurmCluster(directory)
    try:
        cluster.start()
        yield cluster
    finally:
        cluster.stop()
        shutil.rmtree(directory, ignore_errors=True)


def without_measurements(path):
    rows = [json.loads(line) for line in path.read_text().splitlines()]
    return [{key: value for key, value in row.items() if key not in MEASUREMENTS} for row in rows]


def test_a_job_array_sweep_merges_into_the_single_machine_sweep(slurm_cluster, curvebench_bin, run):
    work = slurm_cluster.directory / "sweep"
    work.mkdir()
    config = work / "config.json"
    config.write_text(json.dumps(CONFIG))
    shards = work / "shards"
    submitted = subprocess.run(
        ["sbatch", f"--array=0-{TASKS - 1}", "--wait", f"--output={work}/task-%a.log", str(SBATCH_SCRIPT), str(config),
         str(shards)],
        env={**slurm_cluster.environment, "CURVEBENCH_BIN": os.path.abspath(curvebench_bin)}, cwd=work, capture_output=True, text=True,
        timeout=240)
    task_logs = "\n".join(f"--- {log}:\n{log.read_text()}" for log in sorted(work.glob("task-*.log")))
    if submitted.returncode != 0:
        slurm_cluster.fail(f"sbatch --wait exited with {submitted.returncode}: {submitted.stderr}\n{task_logs}")
    shard_files = sorted(shards.glob("shard-*-of-4.jsonl"))
    assert [f.name for f in shard_files] == [f"shard-{i}-of-4.jsonl" for i in range(TASKS)], task_logs

    merged = work / "merged.jsonl"
    result = run("merge", config, *shard_files, "--out", merged)
    assert result.returncode == 0, result.stderr
    single = work / "single.jsonl"
    result = run("sweep", config, "--out", single, "--quiet", timeout=300)
    assert result.returncode == 0, result.stderr
    rows = without_measurements(merged)
    assert len(rows) == 2 * 2 * 2 * 3 and all(row["status"] == "ok" for row in rows)
    assert rows == without_measurements(single)
