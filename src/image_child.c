/* image_child.c: image_read and image_indices, with OpenImageIO and libpng
 * in a child process (src/loader.h): a decoder that crashes or hangs on a hostile
 * file makes an error that names the file, and eclat goes on. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "host_memory.h"
#include "image.h"
#include "loader.h"

struct image_job {
	const char *path;
	const image_limits *lim;
	image_data *out;
};

/* What crosses the pipe ahead of the pixels (or of the error's text). */
struct image_head {
	int rc, width, height, encoding, premultiplied, channels, bits;
	float gamma;
	char format[32];
};

static int image_work(int fd, void *arg)
{
	struct image_job *j = arg;
	image_data d;
	char err[LOADER_ERR_LEN] = "";
	struct image_head h = { 0 };
	h.rc = image_read_here(j->path, j->lim->max_texels, &d, err, sizeof err);
	if (h.rc)
		return loader_write(fd, &h, sizeof h) || loader_write(fd, err, sizeof err);
	h.width = d.width;
	h.height = d.height;
	h.encoding = d.encoding;
	h.premultiplied = d.premultiplied;
	h.channels = d.channels;
	h.bits = d.bits;
	h.gamma = d.gamma;
	memcpy(h.format, d.format, sizeof h.format);
	return loader_write(fd, &h, sizeof h) ||
	       loader_write(fd, d.rgba, (size_t)d.width * d.height * 4 * sizeof *d.rgba);
}

static int image_take(int fd, void *arg, char *err, size_t errlen)
{
	struct image_job *j = arg;
	struct image_head h;
	if (loader_read(fd, &h, sizeof h))
		return -2;
	if (h.rc)
		return loader_take_error(fd, err, errlen);
	/* the child checked the size; a child gone wrong must not make this one allocate */
	if (h.width <= 0 || h.height <= 0 || (long)h.width * h.height > j->lim->max_texels)
		return -2;
	size_t n = (size_t)h.width * h.height * 4;
	if (j->lim->max_bytes > 0 && (double)n * sizeof(float) > j->lim->max_bytes) {
		char need[32], left[32];
		host_memory_format((double)n * sizeof(float), need, sizeof need);
		host_memory_format(j->lim->max_bytes, left, sizeof left);
		snprintf(err, errlen, "its %d x %d pixels need %s, more than the %s of memory left to the scene "
		         "(--memory-limit)", h.width, h.height, need, left);
		return -1;
	}
	float *rgba = malloc(n * sizeof *rgba);
	if (!rgba) {
		snprintf(err, errlen, "out of memory for %d x %d pixels", h.width, h.height);
		return -1;
	}
	if (loader_read(fd, rgba, n * sizeof *rgba)) {
		free(rgba);
		return -2;
	}
	image_data *d = j->out;
	*d = (image_data){ .rgba = rgba, .width = h.width, .height = h.height, .encoding = h.encoding,
	                   .gamma = h.gamma, .premultiplied = h.premultiplied, .channels = h.channels,
	                   .bits = h.bits };
	memcpy(d->format, h.format, sizeof d->format);
	d->format[sizeof d->format - 1] = '\0';
	return 0;
}

int image_read(const char *path, const image_limits *lim, image_data *out, char *err, size_t errlen)
{
	memset(out, 0, sizeof *out);
	const char *not_file = loader_not_a_file(path);
	if (not_file) {
		snprintf(err, errlen, "%s", not_file);
		return -1;
	}
	struct image_job j = { path, lim, out };
	return loader_run("OpenImageIO", lim->time_limit, image_work, image_take, &j, err, errlen);
}

struct indices_job {
	const char *path;
	long max_texels;
	unsigned char *px;
	int width, height, kind;
};

static int indices_work(int fd, void *arg)
{
	struct indices_job *j = arg;
	int head[3] = { 0, 0, 0 };
	unsigned char *px = NULL;
	head[0] = image_indices_here(j->path, j->max_texels, &px, &head[1], &head[2]);
	return loader_write(fd, head, sizeof head) ||
	       (head[0] && loader_write(fd, px, (size_t)head[1] * head[2]));
}

static int indices_take(int fd, void *arg, char *err, size_t errlen)
{
	(void)err;
	(void)errlen;
	struct indices_job *j = arg;
	int head[3];
	if (loader_read(fd, head, sizeof head))
		return -2;
	if (!head[0])
		return 0;
	if (head[1] <= 0 || head[2] <= 0 || (long)head[1] * head[2] > j->max_texels)
		return -2;
	j->px = malloc((size_t)head[1] * head[2]);
	if (!j->px || loader_read(fd, j->px, (size_t)head[1] * head[2])) {
		free(j->px);
		j->px = NULL;
		return -2;
	}
	j->width = head[1];
	j->height = head[2];
	j->kind = head[0];
	return 0;
}

int image_indices(const char *path, const image_limits *lim, unsigned char **out, int *width, int *height)
{
	*out = NULL;
	if (loader_not_a_file(path))
		return 0;
	long max = lim->max_texels;
	if (lim->max_bytes > 0 && lim->max_bytes < max)
		max = (long)lim->max_bytes;   /* a byte a pixel */
	struct indices_job j = { path, max, NULL, 0, 0, 0 };
	char err[LOADER_ERR_LEN];
	if (loader_run("libpng or giflib", lim->time_limit, indices_work, indices_take, &j, err, sizeof err) || !j.px)
		return 0;   /* image_read, which ran first, reads the same file and says what is wrong */
	*out = j.px;
	*width = j.width;
	*height = j.height;
	return j.kind == IMAGE_INDICES_GIF ? IMAGE_INDICES_GIF : IMAGE_INDICES_PNG;
}
