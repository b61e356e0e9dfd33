/* fuzz_merge.c: libFuzzer target for `eclat merge` (src/merge.c) and the EXR
 * reader under it (split_read, src/image_split.cpp): the parts of a split
 * render come from other machines, and a part may be cut, foreign or made to
 * lie. An input is up to four part files separated by the line "--part--";
 * they are written to a scratch folder and merged into a PNG there, as
 * `eclat merge p0.exr p1.exr ... -o out.png` would. A refusal is one outcome;
 * a crash, a hang, a leak or a sanitizer report is a finding. So is a merge
 * that says it succeeded without writing its image, one that failed and
 * wrote it, and a temporary file left behind.
 *
 *   make fuzz FUZZ_SECONDS=60
 *   fuzz/fuzz_merge crash-...   (replays one input with its messages) */
#include <dirent.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "merge.h"

#define MAX_PARTS 4
static const char marker[] = "\n--part--\n";

static char dir[64];

static void scratch(void)
{
	if (dir[0])
		return;
	const char *t = getenv("TMPDIR") ? getenv("TMPDIR") : "/tmp";
	snprintf(dir, sizeof dir, "%.40s/fuzz_merge.XXXXXX", t);
	if (!mkdtemp(dir))
		abort();
}

static const uint8_t *find(const uint8_t *p, const uint8_t *end)
{
	size_t m = sizeof marker - 1;
	for (; p + m <= end; p++)
		if (memcmp(p, marker, m) == 0)
			return p;
	return NULL;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	scratch();
	char paths[MAX_PARTS][96], out[96];
	char *argv[MAX_PARTS + 4];
	int argc = 0, n = 0;
	argv[argc++] = "merge";
	const uint8_t *p = data, *end = data + size;
	while (n < MAX_PARTS && p <= end) {
		const uint8_t *next = find(p, end);
		const uint8_t *stop = next ? next : end;
		snprintf(paths[n], sizeof paths[n], "%s/p%d.exr", dir, n);
		FILE *f = fopen(paths[n], "wb");
		if (!f)
			abort();
		if (stop > p && fwrite(p, 1, (size_t)(stop - p), f) != (size_t)(stop - p))
			abort();
		fclose(f);
		argv[argc++] = paths[n++];
		if (!next)
			break;
		p = next + sizeof marker - 1;
	}
	snprintf(out, sizeof out, "%s/out.png", dir);
	unlink(out);
	argv[argc++] = "-o";
	argv[argc++] = out;
	argv[argc] = NULL;
	int rc = merge_main(argc, argv);
	struct stat st;
	int wrote = stat(out, &st) == 0 && st.st_size > 0;
	if (rc == 0 && !wrote)
		abort();   /* a merge that succeeded wrote its image */
	if (rc != 0 && wrote)
		abort();   /* a refused merge writes nothing */
	for (int i = 0; i < n; i++)
		unlink(paths[i]);
	unlink(out);
	DIR *d = opendir(dir);
	if (!d)
		abort();
	for (struct dirent *e; (e = readdir(d));)
		if (strcmp(e->d_name, ".") && strcmp(e->d_name, ".."))
			abort();   /* a temporary file left behind */
	closedir(d);
	return 0;
}
