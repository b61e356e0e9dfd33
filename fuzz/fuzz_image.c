/* fuzz_image.c: libFuzzer target for image files as eclat reads them for an
 * image_map or a height_field (src/image_child.c): OpenImageIO and libpng in a
 * child process with a time limit, the header's size checked before decoding,
 * the pixels sent back through a pipe and checked again here. A library's own
 * crash is an error, as in eclat; what is fuzzed is eclat's part (the checks,
 * the transfer, the cleanup, no hang), and the answer must be consistent: an
 * image within the limits, or an error with a message.
 * An input is "EXT\n" and the bytes of an image file: the first line picks the
 * extension (png, jpg, exr, gif, tga, hdr, tif...), the way a scene names its
 * file; the rest is written to a temporary file.
 *
 *   make fuzz FUZZ_SECONDS=60
 *   FUZZ_VERBOSE=1 fuzz/fuzz_image crash-...   (replays one input) */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "image.h"

#define LOADER_SECONDS 3             /* well under libFuzzer's -timeout */
#define MAX_TEXELS (1L << 20)        /* small: the fuzzer's memory limit is the parent's */

static size_t extension(const uint8_t *data, size_t size, char ext[8])
{
	size_t n = 0;
	while (n < size && n < 6 && data[n] != '\n' &&
	       ((data[n] >= 'a' && data[n] <= 'z') || (data[n] >= '0' && data[n] <= '9')))
		n++;
	if (n == 0 || n > 5 || n >= size || data[n] != '\n') {
		strcpy(ext, "png");
		return 0;
	}
	memcpy(ext, data, n);
	ext[n] = '\0';
	return n + 1;
}

/* OpenImageIO finds its format plugins on first use: found here, once, each
 * child inherits them instead of looking again. */
int LLVMFuzzerInitialize(int *argc, char ***argv)
{
	(void)argc;
	(void)argv;
	static const char *const names[] = { "a.png", "a.jpg", "a.exr", "a.gif", "a.tga", "a.hdr", "a.tif", "a.bmp" };
	for (size_t i = 0; i < sizeof names / sizeof *names; i++)
		image_format_known(names[i]);
	return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	char ext[8], path[64];
	size_t skip = extension(data, size, ext);
	const char *dir = getenv("TMPDIR") ? getenv("TMPDIR") : "/tmp";
	snprintf(path, sizeof path, "%.40s/fuzz_image_XXXXXX.%s", dir, ext);
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
	image_limits lim = { MAX_TEXELS, LOADER_SECONDS, 64.0 * MAX_TEXELS };
	image_data d;
	char err[512] = "";
	if (image_read(path, &lim, &d, err, sizeof err) == 0) {
		if (!d.rgba || d.width <= 0 || d.height <= 0 || (long)d.width * d.height > MAX_TEXELS)
			abort();
		volatile float sum = 0;   /* every pixel arrived and may be read */
		for (long i = 0; i < 4L * d.width * d.height; i++)
			sum += d.rgba[i];
		free(d.rgba);
		unsigned char *idx;
		int w, h;
		/* giflib or libpng may see other sizes than OpenImageIO (a GIF's
		 * screen against its frame): every caller then takes the image as
		 * having no palette (eval_pattern.c, eval_hfield.c), so only the
		 * read itself is checked here */
		if (image_indices(path, &lim, &idx, &w, &h))
			free(idx);
	} else if (!err[0]) {
		abort();   /* an error says why */
	}
	unlink(path);
	return 0;
}
