/* fuzz_mesh.c: libFuzzer target for the mesh loader (src/mesh_io.c, assimp), as
 * eclat runs it: assimp in a child process, so its own crashes are errors and
 * what is fuzzed is eclat's part (checks, transfer, cleanup, no hang).
 * An input is "EXT\n" and the bytes of a mesh file: the first line picks the file
 * extension (obj, ply, stl, off, gltf...), the way a scene names its file; the
 * rest is written to a temporary file that mesh_io_load reads.
 *
 *   make fuzz FUZZ_SECONDS=60
 *   FUZZ_VERBOSE=1 fuzz/fuzz_mesh crash-...   (replays one input) */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "mesh_io.h"

/* assimp loops for ever on some inputs (a truncated binary PLY header); eclat's
 * answer is the loader's time limit, tried here with a limit well under
 * libFuzzer's -timeout, which then catches hangs in eclat's own part. */
#define LOADER_SECONDS 3

/* The extension on the first line, when it is 1 to 5 letters or digits. */
static size_t extension(const uint8_t *data, size_t size, char ext[8])
{
	size_t n = 0;
	while (n < size && n < 6 && data[n] != '\n' &&
	       ((data[n] >= 'a' && data[n] <= 'z') || (data[n] >= '0' && data[n] <= '9')))
		n++;
	if (n == 0 || n > 5 || n >= size || data[n] != '\n') {
		strcpy(ext, "obj");
		return 0;
	}
	memcpy(ext, data, n);
	ext[n] = '\0';
	return n + 1;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	char ext[8], path[64];
	size_t skip = extension(data, size, ext);
	const char *dir = getenv("TMPDIR") ? getenv("TMPDIR") : "/tmp";
	snprintf(path, sizeof path, "%.40s/fuzz_mesh_XXXXXX.%s", dir, ext);
	int fd = mkstemps(path, (int)strlen(ext) + 1);
	if (fd < 0)
		return 0;
	FILE *f = fdopen(fd, "wb");
	if (!f) {
		close(fd);
		unlink(path);
		return 0;
	}
	fwrite(data + skip, 1, size - skip, f);
	fclose(f);
	scene_mesh m;
	char err[512];
	if (mesh_io_load(path, LOADER_SECONDS, 0, &m, err, sizeof err) == 0)
		scene_mesh_free(&m);
	unlink(path);
	return 0;
}
