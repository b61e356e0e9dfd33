/* split_child.c: split_read with OpenEXR in a child process (src/loader.h).
 * eclat merge and --resume read EXRs that other machines wrote; a cut or
 * forged one may make OpenEXR allocate what its header claims, or crash, and
 * that must be an error that names the file. What crosses the pipe is checked
 * again here before anything is allocated for it. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "host_memory.h"
#include "loader.h"
#include "split.h"

/* as long as the slowest disk needs for the largest part: a hang is a hostile file */
#define SPLIT_READ_SECONDS 300
#define MAX_SIDE 65536

struct split_job {
	const char *path;
	split_info *info;
	int64_t **sums;
};

/* What crosses the pipe ahead of the strings and the sums (or the error). */
struct split_head {
	int rc, width, height, region[4];
	long total, first, count, samples;
	float gamma;
	size_t len[3];   /* scene, options, files, each with its '\0' */
};

int split_size_check(long width, long height, char *err, size_t errlen)
{
	if (width < 1 || height < 1 || width > MAX_SIDE || height > MAX_SIDE) {
		snprintf(err, errlen, "its header says %ld x %ld pixels, more than the %d on a side a part may have",
		         width, height, MAX_SIDE);
		return -1;
	}
	/* the sums, and on the way in the twelve float channels they are kept in */
	double need = (double)width * (double)height * (4 * sizeof(int64_t) + 12 * sizeof(float));
	double left = host_memory_available();
	if (left > 0 && need > left) {
		char a[32], b[32];
		host_memory_format(need, a, sizeof a);
		host_memory_format(left, b, sizeof b);
		snprintf(err, errlen, "its %ld x %ld pixels need %s, more than the %s of memory left", width, height, a, b);
		return -1;
	}
	return 0;
}

static int split_work(int fd, void *arg)
{
	struct split_job *j = arg;
	split_info info;
	int64_t *sums = NULL;
	char err[LOADER_ERR_LEN] = "";
	struct split_head h = { 0 };
	h.rc = split_read_here(j->path, &info, &sums, err, sizeof err);
	if (h.rc)
		return loader_write(fd, &h, sizeof h) || loader_write(fd, err, sizeof err);
	h.width = info.width;
	h.height = info.height;
	memcpy(h.region, info.region, sizeof h.region);
	h.total = info.total;
	h.first = info.first;
	h.count = info.count;
	h.samples = info.samples;
	h.gamma = info.gamma;
	const char *text[3] = { info.scene, info.key.options, info.key.files };
	for (int i = 0; i < 3; i++)
		h.len[i] = strlen(text[i] ? text[i] : "") + 1;
	int bad = loader_write(fd, &h, sizeof h);
	for (int i = 0; i < 3 && !bad; i++)
		bad = loader_write(fd, text[i] ? text[i] : "", h.len[i]);
	return bad || loader_write(fd, sums, (size_t)h.width * h.height * 4 * sizeof *sums);
}

/* A string of len bytes, '\0' at its end and nowhere before. */
static char *take_string(int fd, size_t len)
{
	if (len < 1 || len > (size_t)1 << 28)
		return NULL;
	char *s = malloc(len);
	if (!s || loader_read(fd, s, len) || s[len - 1] != '\0' || strlen(s) != len - 1) {
		free(s);
		return NULL;
	}
	return s;
}

static int split_take(int fd, void *arg, char *err, size_t errlen)
{
	struct split_job *j = arg;
	struct split_head h;
	if (loader_read(fd, &h, sizeof h))
		return -2;
	if (h.rc)
		return loader_take_error(fd, err, errlen);
	if (split_size_check(h.width, h.height, err, errlen))
		return -1;
	split_info *info = j->info;
	*info = (split_info){ .width = h.width, .height = h.height, .total = h.total, .first = h.first,
	                      .count = h.count, .samples = h.samples, .gamma = h.gamma };
	memcpy(info->region, h.region, sizeof info->region);
	char **text[3] = { &info->scene, &info->key.options, &info->key.files };
	for (int i = 0; i < 3; i++)
		if (!(*text[i] = take_string(fd, h.len[i]))) {
			split_info_free(info);
			return -2;
		}
	size_t n = (size_t)h.width * h.height * 4;
	int64_t *sums = malloc(n * sizeof *sums);
	if (!sums || loader_read(fd, sums, n * sizeof *sums)) {
		free(sums);
		split_info_free(info);
		if (!sums) {
			snprintf(err, errlen, "out of memory for its %d x %d pixels", h.width, h.height);
			return -1;
		}
		return -2;
	}
	*j->sums = sums;
	return 0;
}

int split_read(const char *path, split_info *info, int64_t **sums, char *err, size_t errlen)
{
	*info = (split_info){ 0 };
	*sums = NULL;
	const char *not_file = loader_not_a_file(path);
	if (not_file) {
		snprintf(err, errlen, "%s", not_file);
		return -1;
	}
	struct split_job j = { path, info, sums };
	return loader_run("OpenEXR", SPLIT_READ_SECONDS, split_work, split_take, &j, err, errlen);
}
