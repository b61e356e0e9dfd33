#!/bin/sh
# Renders one frame on a Slurm cluster: PARTS array tasks of sample ranges,
# then a merge job that runs when all of them have succeeded.
#   farm.sh SCENE.scn IMAGE SAMPLES PARTS [ECLAT OPTIONS...]
# Prints the two job ids. The parts go beside IMAGE, as IMAGE's stem.partI.exr.
here=$(dirname "$0")
scene=${1:?usage: farm.sh SCENE.scn IMAGE SAMPLES PARTS [ECLAT OPTIONS...]} image=${2:?image}
samples=${3:?samples} parts=${4:?parts}
shift 4
prefix=${image%.*}
array=$(sbatch --parsable --array=0-$((parts - 1)) "$here/render.sbatch" "$scene" "$prefix" "$samples" \
	"$parts" "$@") || exit 1
merge=$(sbatch --parsable --dependency=afterok:"$array" --kill-on-invalid-dep=yes "$here/merge.sbatch" \
	"$prefix" "$parts" "$image") || exit 1
echo "render array $array, merge $merge"
