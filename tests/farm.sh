#!/bin/sh
# make check-farm: examples/farm on a real one-node Slurm cluster on localhost.
# munged (its own key and socket), slurmctld and slurmd run as the current
# user from a config generated in a folder under the build tree, and are
# stopped, with every process of theirs, however the test ends. A 4-task
# array renders a frame's sample ranges and a dependent job merges them: the
# image must equal the single-process render. Faults: a task killed (SIGKILL
# through scancel) after its first checkpoint is run again and goes on from it,
# and the merge is still exact; a corrupt part is named by merge. An array of
# one task a frame (frames.sbatch) gives the frames of one animated run. When the
# cluster cannot start, the test fails saying why (never skips).
# Environment: ECLAT, top_srcdir, top_builddir, OIIOTOOL (as make check's).
set -u
: "${ECLAT:?}" "${top_srcdir:?}" "${top_builddir:?}"
OIIOTOOL=${OIIOTOOL:-oiiotool}
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
pass() { echo "ok: $*"; }

mkdir -p "$top_builddir/tests" || exit 1
dir=$(mktemp -d "$top_builddir/tests/farm.XXXXXX") || exit 1
dir=$(cd "$dir" && pwd -P)
# Only the daemons and the jobs get SLURM_CONF: it marks this cluster's
# processes (a job step inherits it), and never this script's own.
conf=$dir/slurm.conf
sl() { SLURM_CONF=$conf "$@"; }
pids=

# Stops our daemons, then any process left that carries our SLURM_CONF (job
# steps that slurmd started and that outlived it): this cluster's only.
stop_cluster() {
	[ -n "${pids:-}" ] && sl scancel --quiet --user="$(id -un)" 2> /dev/null
	for pid in $pids; do kill "$pid" 2> /dev/null; done
	sleep 1
	for pid in $pids; do kill -9 "$pid" 2> /dev/null; done
	for env in /proc/[0-9]*/environ; do
		pid=${env#/proc/}
		pid=${pid%/environ}
		tr '\0' '\n' 2> /dev/null < "$env" | grep -qxF "SLURM_CONF=$conf" &&
			kill -9 "$pid" 2> /dev/null
	done
	for pid in $pids; do wait "$pid" 2> /dev/null; done
	pids=
}
cleanup() {
	status=$?
	stop_cluster
	if [ "$failures" -eq 0 ] && [ "$status" -eq 0 ]; then rm -rf "$dir"; else echo "farm: logs kept in $dir"; fi
}
trap cleanup EXIT
trap 'exit 1' INT TERM HUP

# die WHY: the cluster could not be used; the test fails (there is no skip).
die() {
	echo "FAIL: $*"
	for log in "$dir"/*.log; do [ -f "$log" ] && { echo "--- $log"; tail -n 15 "$log"; }; done
	echo "check-farm: FAIL (the Slurm cluster: $*)"
	exit 1
}

for tool in munged slurmctld slurmd sbatch squeue scancel scontrol; do
	command -v "$tool" > /dev/null || die "no $tool: install slurm-wlm, slurmctld, slurmd and munge (./bootstrap does)"
done

# Two free ports, by asking the kernel for them.
ports=$(python3 -c 'import socket
s=[socket.socket() for _ in range(2)]
[x.bind(("127.0.0.1", 0)) for x in s]
print(" ".join(str(x.getsockname()[1]) for x in s))') || die "no free ports"
set -- $ports
ctld_port=$1 slurmd_port=$2
user=$(id -un)
cpus=$(nproc)

dd if=/dev/urandom of="$dir/munge.key" bs=1024 count=1 2> /dev/null && chmod 400 "$dir/munge.key"
chmod 700 "$dir"
munged --foreground --force --socket="$dir/munge.socket" --key-file="$dir/munge.key" \
	--pid-file="$dir/munged.pid" --log-file="$dir/munged.log" --seed-file="$dir/munged.seed" 2> "$dir/munged.err" &
pids="$pids $!"

mkdir -p "$dir/state" "$dir/spool"
: > "$dir/plugstack.conf"
cat > "$conf" <<EOF
ClusterName=eclatfarm
SlurmctldHost=localhost(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
SlurmUser=$user
SlurmdUser=$user
AuthType=auth/munge
AuthInfo=socket=$dir/munge.socket
CredType=cred/munge
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/slurmctld.log
SlurmdLogFile=$dir/slurmd.log
SlurmdDebug=info
PlugStackConfig=$dir/plugstack.conf
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
SwitchType=switch/none
MpiDefault=none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SchedulerType=sched/backfill
ReturnToService=2
NodeName=localhost NodeAddr=127.0.0.1 CPUs=$cpus State=UNKNOWN
PartitionName=farm Nodes=localhost Default=YES MaxTime=INFINITE State=UP
EOF

i=0
while [ ! -S "$dir/munge.socket" ]; do
	i=$((i + 1))
	[ $i -le 50 ] || die "munged did not start: $(cat "$dir/munged.err")"
	sleep 0.1
done
SLURM_CONF=$conf slurmctld -D -i > "$dir/slurmctld.out" 2>&1 &
pids="$pids $!"
SLURM_CONF=$conf slurmd -D -N localhost > "$dir/slurmd.out" 2>&1 &
pids="$pids $!"
i=0
until sl sinfo -h -N -o '%T' 2> /dev/null | grep -qE '^(idle|mixed|allocated)'; do
	i=$((i + 1))
	[ $i -le 60 ] || die "the node did not come up in 60 s: $(sl sinfo -h -N -o '%T %E' 2>&1; tail -n 3 "$dir/slurmd.out" "$dir/slurmctld.out")"
	sleep 1
done
pass "a one-node Slurm cluster on localhost ($cpus CPUs)"

farm=$top_srcdir/examples/farm
scene=$dir/scene.scn
cp "$top_srcdir/tests/render/cornell.scn" "$scene"
export ECLAT
cd "$dir" || exit 1

# wait_job ID: until it has left the queue (120 s at most)
wait_job() {
	i=0
	while sl squeue -h -j "$1" 2> /dev/null | grep -q .; do
		i=$((i + 1))
		[ $i -le 240 ] || { fail "job $1 still queued after 120 s: $(sl squeue -j "$1" 2>&1)"; return 1; }
		sleep 0.5
	done
}
same() {
	"$OIIOTOOL" -a --fail 0 --warn 0 "$2" "$3" --diff > diff.out 2>&1 && pass "$1" ||
		fail "$1: $(grep -E 'Max error|pixels|rror' diff.out | head -2 | tr '\n' ' ')"
}

# A split frame: farm.sh submits the array and the dependent merge.
"$ECLAT" -q -W 32 -H 24 -s 16 -o full.exr "$scene" || fail "the single-process render"
jobs=$(sl "$farm/farm.sh" "$scene" "$dir/frame.exr" 16 4 -W 32 -H 24) || die "farm.sh could not submit: $jobs"
merge=${jobs##* }
wait_job "$merge"
[ -f frame.exr ] && same "4 array tasks and a dependent merge give the single-process image" full.exr frame.exr ||
	fail "no merged image: $(cat eclat-*.log 2>/dev/null | tail -n 5)"

# A task killed after its first checkpoint, run again, goes on from it.
N=24000
"$ECLAT" -q -W 12 -H 12 -s $N -o whole.exr "$scene"
array=$(CHECKPOINT=0.3 sl sbatch --parsable --array=0-3 "$farm/render.sbatch" "$scene" "$dir/k" $N 4 -W 12 -H 12)
i=0
while [ ! -f k.part1.exr ] && [ $i -lt 600 ]; do sleep 0.1; i=$((i + 1)); done
sl scancel --signal=KILL "${array}_1"
wait_job "$array"
n=$("$OIIOTOOL" --info -v k.part1.exr 2> /dev/null | sed -n 's/.*eclat:samples: *\([0-9]*\).*/\1/p')
if [ -n "$n" ] && [ "$n" -lt $((N / 4)) ]; then
	pass "scancel --signal=KILL left task 1 with a checkpoint of $n of its $((N / 4)) samples"
else
	fail "task 1 was not killed in the middle (its part holds '$n' samples)"
fi
"$ECLAT" merge k.part0.exr k.part1.exr k.part2.exr k.part3.exr -o killed.exr 2> merge.err
grep -qF "'k.part1.exr': holds $n of its $((N / 4)) samples" merge.err && [ ! -e killed.exr ] &&
	pass "merge names the killed task's part" || fail "merge of a killed part: $(cat merge.err)"
again=$(CHECKPOINT=0.3 sl sbatch --parsable --array=1 "$farm/render.sbatch" "$scene" "$dir/k" $N 4 -W 12 -H 12)
merge=$(sl sbatch --parsable --dependency=afterok:"$again" "$farm/merge.sbatch" "$dir/k" 4 "$dir/k.exr")
wait_job "$merge"
[ -f k.exr ] && same "task 1 run again resumes; the merge equals the single-process image" whole.exr k.exr ||
	fail "no merged image after the re-run: $(tail -n 5 eclat-*.log 2>/dev/null)"

# An animation: one array task a frame gives each frame of the single run.
cat > anim.scn <<'EOF2'
camera { location <0, 1, -4> look_at 0 }
light_source { <2, 4, -3> color rgb 1 }
sphere { <clock * 2 - 1, 0, 0>, 0.5 pigment { rgb <1, 0.5, 0.2> } }
plane { y, -0.5 pigment { rgb 0.8 } }
EOF2
"$ECLAT" -q -W 32 -H 24 -s 8 +KFI1 +KFF4 -o one.png anim.scn || fail "the single-process animation"
array=$(sl sbatch --parsable --array=1-4 "$farm/frames.sbatch" "$dir/anim.scn" "$dir/farm.png" 1 4 -W 32 -H 24 -s 8) ||
	fail "frames.sbatch could not be submitted: $array"
wait_job "$array"
for f in 1 2 3 4; do
	[ -f farm$f.png ] && same "array task $f renders frame $f of the animation as the single run does" one$f.png farm$f.png ||
		fail "no frame $f: $(tail -n 3 eclat-frames-*_$f.log 2>/dev/null)"
done
"$OIIOTOOL" -a --fail 0 --warn 0 one1.png one4.png --diff > /dev/null 2>&1 &&
	fail "frames 1 and 4 are the same image: the clock did not move" || pass "the clock moves between frames"

# A corrupt part: merge names it and writes nothing.
head -c 2000 frame.part2.exr > cut && mv cut frame.part2.exr
merge=$(sl sbatch --parsable "$farm/merge.sbatch" "$dir/frame" 4 "$dir/corrupt.exr")
wait_job "$merge"
grep -qF "frame.part2.exr'" "eclat-merge-$merge.log" && [ ! -e corrupt.exr ] &&
	pass "a corrupt part is named by the merge job, which writes nothing" ||
	fail "corrupt part: $(cat "eclat-merge-$merge.log" 2>&1)"

stop_cluster
left=$(for env in /proc/[0-9]*/environ; do tr '\0' '\n' 2> /dev/null < "$env" | grep -qxF "SLURM_CONF=$conf" && echo "$env"; done)
[ -z "$left" ] && pass "nothing of the cluster left running" || fail "still running: $left"
if [ "$failures" -eq 0 ]; then echo "check-farm: PASS"; else echo "check-farm: FAIL ($failures checks)"; exit 1; fi
