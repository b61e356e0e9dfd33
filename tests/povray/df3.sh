#!/bin/sh
# Makes the density_file scenes' tiny df3 files here (they are committed; run
# this again only to change them): a df3 file is three big-endian 16-bit
# sizes nx, ny, nz, then the voxels, x fastest, big-endian. One file for each
# voxel width: 1, 2 and 4 bytes. The values are a scramble of the voxel's
# place, so that every voxel differs from its neighbours and a wrong index or
# a wrong neighbour shows, with the edges (where POV-Ray's interpolations wrap
# around) as busy as the middle.
cd "$(dirname "$0")" || exit 1
byte() { printf "\\$(printf %03o "$1")"; }
# df3 FILE NX NY NZ WIDTH
df3() {
	{
		for s in "$2" "$3" "$4"; do byte $((s >> 8)); byte $((s & 255)); done
		z=0
		while [ $z -lt "$4" ]; do
			y=0
			while [ $y -lt "$3" ]; do
				x=0
				while [ $x -lt "$2" ]; do
					i=$(( (z * $3 + y) * $2 + x + 1 ))
					v=$(( (i * i * 2654435761 + i * 40503) % 4294967296 ))
					k=0   # the value's top WIDTH bytes, the high one first
					while [ $k -lt "$5" ]; do byte $(( (v >> (24 - 8 * k)) & 255 )); k=$((k + 1)); done
					x=$((x + 1))
				done
				y=$((y + 1))
			done
			z=$((z + 1))
		done
	} > "$1"
}
df3 voxels8.df3 5 4 3 1
df3 voxels16.df3 6 5 4 2
df3 voxels32.df3 3 4 2 4
