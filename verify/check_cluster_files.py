#!/usr/bin/python3
"""Static checks of the files that run the sweep's shards elsewhere:
the GitHub Actions matrix workflow and the Slurm job-array scripts cannot run
here, so ctest verify_cluster_files checks that they parse and say what
docs/verify.md says they do.

    /usr/bin/python3 verify/check_cluster_files.py SOURCE_DIR

Workflow (.github/workflows/verify-sweep.yml, parsed with PyYAML): the matrix
lists shards 0..SHARDS-1 exactly; each matrix job runs skelconv-verify with
--shard <matrix.shard>/$SHARDS and uploads its report; the merge job needs the
shard job, downloads every shard report and runs `skelconv-verify merge`.
Slurm (scripts/slurm/*): `bash -n` passes; the submit script asks for
--array=0-(N-1) and makes the merge depend on the array with afterok; the
array task runs shard $SLURM_ARRAY_TASK_ID/N. (ctest verify_slurm_scripts
also runs them end to end with a stand-in sbatch.)
"""
import subprocess
import sys
from pathlib import Path

import yaml

problems = []


def check(condition, message):
    if not condition:
        problems.append(message)


def steps_text(job):
    return "\n".join(str(step.get("run", "")) + str(step.get("uses", "")) + str(step.get("with", ""))
                     for step in job.get("steps", []))


def check_workflow(path):
    try:
        workflow = yaml.safe_load(path.read_text(encoding="utf-8"))
    except (OSError, yaml.YAMLError) as error:
        problems.append(f"{path}: {error}")
        return
    triggers = workflow.get("on", workflow.get(True))  # YAML 1.1 reads a bare `on` as true
    check(isinstance(triggers, dict) and "workflow_dispatch" in triggers, f"{path}: no workflow_dispatch trigger")
    shards = workflow.get("env", {}).get("SHARDS")
    check(isinstance(shards, int) and shards >= 1, f"{path}: env.SHARDS must be a positive integer")
    jobs = workflow.get("jobs", {})
    shard_job, merge_job = jobs.get("shard", {}), jobs.get("merge", {})
    matrix = shard_job.get("strategy", {}).get("matrix", {}).get("shard")
    check(isinstance(shards, int) and matrix == list(range(shards or 0)),
          f"{path}: jobs.shard.strategy.matrix.shard must be 0..SHARDS-1 ({shards}), got {matrix}")
    check(shard_job.get("strategy", {}).get("fail-fast") is False,
          f"{path}: jobs.shard.strategy.fail-fast must be false (the merge judges)")
    text = steps_text(shard_job)
    check('--shard "${{ matrix.shard }}/$SHARDS"' in text, f"{path}: the shard job does not run --shard k/SHARDS")
    check("actions/upload-artifact" in text, f"{path}: the shard job does not upload its report")
    needs = merge_job.get("needs")
    check(needs == "shard" or (isinstance(needs, list) and "shard" in needs), f"{path}: jobs.merge must need shard")
    text = steps_text(merge_job)
    check("actions/download-artifact" in text, f"{path}: the merge job does not download the shard reports")
    check("skelconv-verify merge shards/shard-*-of-$SHARDS.json" in text, f"{path}: the merge job does not merge")


def check_slurm(directory):
    scripts = sorted(directory.glob("*"))
    check(len(scripts) == 3, f"{directory}: expected submit_sweep.sh and two .sbatch scripts")
    for script in scripts:
        result = subprocess.run(["bash", "-n", str(script)], capture_output=True, text=True, check=False)
        check(result.returncode == 0, f"{script}: bash -n: {result.stderr.strip()}")
    submit = (directory / "submit_sweep.sh").read_text(encoding="utf-8")
    check("--array=0-$((shards - 1))" in submit, "submit_sweep.sh: no --array=0-(N-1)")
    check('--dependency=afterok:"$array_job"' in submit, "submit_sweep.sh: the merge does not depend on the array")
    shard = (directory / "verify_shard.sbatch").read_text(encoding="utf-8")
    check('k="${SLURM_ARRAY_TASK_ID:?' in shard and '--shard "$k/$shards"' in shard,
          "verify_shard.sbatch: does not run shard $SLURM_ARRAY_TASK_ID/N")
    merge = (directory / "merge_shards.sbatch").read_text(encoding="utf-8")
    check('"$verify" merge' in merge, "merge_shards.sbatch: does not run skelconv-verify merge")


def main():
    source = Path(sys.argv[1] if len(sys.argv) > 1 else ".")
    check_workflow(source / ".github/workflows/verify-sweep.yml")
    check_slurm(source / "scripts/slurm")
    for problem in problems:
        print(f"FAIL: {problem}")
    if problems:
        sys.exit(1)
    print("cluster files: the workflow and the Slurm scripts pass their static checks")


if __name__ == "__main__":
    main()
