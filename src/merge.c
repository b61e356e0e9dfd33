/* merge.c: eclat merge: adds the exact sums of a split render's parts (sample
 * ranges, regions, or both) and resolves them as the whole render would, so
 * the image is the one a single run gives, bit for bit. Every part is checked
 * against the first before anything is written. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "film.h"
#include "image.h"
#include "merge.h"
#include "split.h"

struct part {
	const char *path;
	split_info info;
	int64_t *sums;
};

static void usage(FILE *out)
{
	fprintf(out, "Usage: eclat merge [-q] PART.exr... -o IMAGE\n"
	             "Merge the EXRs of a render split with --sample-range or POV-Ray's +SC +SR +EC +ER\n"
	             "into the image one run gives. See SPLITTING AND MERGING in eclat(1).\n");
}

static int complain(const char *path, const char *fmt, const char *a, const char *b)
{
	fprintf(stderr, "eclat: merge: '%s': ", path);
	fprintf(stderr, fmt, a, b);
	fputc('\n', stderr);
	return -1;
}

/* The same render as the first part: size, samples, scene and options. */
static int check_same(const struct part *p, const struct part *first)
{
	const split_info *a = &p->info, *b = &first->info;
	char why[1024], x[64], y[64];
	if (a->width != b->width || a->height != b->height) {
		snprintf(x, sizeof x, "%dx%d", a->width, a->height);
		snprintf(y, sizeof y, "%dx%d", b->width, b->height);
		return complain(p->path, "the image is %s, not %s as in the first part", x, y);
	}
	if (a->total != b->total) {
		snprintf(x, sizeof x, "%ld", a->total);
		snprintf(y, sizeof y, "%ld", b->total);
		return complain(p->path, "a part of a render of %s samples, not %s as the first part", x, y);
	}
	if (split_key_diff(&b->key, &a->key, why, sizeof why))
		return complain(p->path, "not a part of the same render as '%s': %s", first->path, why);
	return 0;
}

static int check_part(const struct part *p)
{
	const split_info *a = &p->info;
	char x[64], y[64];
	if (a->samples != a->count) {
		snprintf(x, sizeof x, "%ld", a->samples);
		snprintf(y, sizeof y, "%ld", a->count);
		return complain(p->path, "holds %s of its %s samples (an interrupted part: finish it with --resume)", x, y);
	}
	if (a->first < 0 || a->count <= 0 || a->first + a->count > a->total || a->region[0] < 0 ||
	    a->region[1] < 0 || a->region[2] >= a->width || a->region[3] >= a->height)
		return complain(p->path, "%s%srecords a sample range or region outside its image", "", "");
	return 0;
}

static int overlaps(const split_info *a, const split_info *b)
{
	return a->region[0] <= b->region[2] && b->region[0] <= a->region[2] && a->region[1] <= b->region[3] &&
	       b->region[1] <= a->region[3] && a->first < b->first + b->count && b->first < a->first + a->count;
}

/* The first samples of pixel (x, y) that no part holds. */
static void gap(const struct part *parts, int n, int x, int y, long total, long *from, long *to)
{
	long at = 0;
	for (int moved = 1; moved;) {
		moved = 0;
		for (int i = 0; i < n; i++)
			if (split_in_region(&parts[i].info, x, y) && parts[i].info.first == at) {
				at += parts[i].info.count;
				moved = 1;
			}
	}
	long next = total;
	for (int i = 0; i < n; i++)
		if (split_in_region(&parts[i].info, x, y) && parts[i].info.first > at && parts[i].info.first < next)
			next = parts[i].info.first;
	*from = at;
	*to = next - 1;
}

/* Adds every part's sums; every pixel must then hold every sample once. */
static int add_parts(const struct part *parts, int n, int64_t *sums)
{
	const split_info *f = &parts[0].info;
	size_t npix = (size_t)f->width * f->height;
	long *count = calloc(npix, sizeof *count);
	if (!count)
		return -1;
	for (int i = 0; i < n; i++) {
		const split_info *a = &parts[i].info;
		for (int y = a->region[1]; y <= a->region[3]; y++)
			for (int x = a->region[0]; x <= a->region[2]; x++) {
				size_t p = (size_t)y * f->width + x;
				count[p] += a->count;
				for (int c = 0; c < 4; c++)
					sums[4 * p + c] += parts[i].sums[4 * p + c];
			}
	}
	int rc = 0;
	for (size_t p = 0; p < npix && rc == 0; p++)
		if (count[p] != f->total) {
			long from, to;
			int x = (int)(p % f->width), y = (int)(p / f->width);
			gap(parts, n, x, y, f->total, &from, &to);
			fprintf(stderr, "eclat: merge: no part holds samples %ld to %ld of pixel %d,%d (of %ld samples): a "
			        "part is missing\n", from, to, x, y, f->total);
			rc = -1;
		}
	free(count);
	return rc;
}

static int write_image(const char *out, const struct part *first, const int64_t *sums)
{
	const split_info *f = &first->info;
	film film;
	char err[512];
	if (film_init(&film, f->width, f->height, 0)) {
		fprintf(stderr, "eclat: merge: out of memory\n");
		return -1;
	}
	film_resolve(&film, sums, f->total, f->gamma);
	split_info whole = *f;
	whole.first = 0;
	whole.count = whole.samples = f->total;
	whole.region[0] = whole.region[1] = 0;
	whole.region[2] = f->width - 1;
	whole.region[3] = f->height - 1;
	image_meta meta = { f->scene, f->total, 0, NULL };
	const char *dot = strrchr(out, '.');
	int rc = dot && strcmp(dot, ".exr") == 0 ? split_write(out, film.rgb, sums, &whole, err, sizeof err)
	                                          : image_write(out, film.rgb, f->width, f->height, &meta, err, sizeof err);
	if (rc)
		fprintf(stderr, "eclat: merge: %s\n", err);
	film_free(&film);
	return rc;
}

static int merge(struct part *parts, int n, const char *out)
{
	char err[512];
	for (int i = 0; i < n; i++) {
		if (split_read(parts[i].path, &parts[i].info, &parts[i].sums, err, sizeof err))
			return complain(parts[i].path, "%s%s", err, "");
		if (check_part(&parts[i]) || (i > 0 && check_same(&parts[i], &parts[0])))
			return -1;
		for (int j = 0; j < i; j++)
			if (overlaps(&parts[j].info, &parts[i].info))
				return complain(parts[i].path, "holds samples of pixels that '%s' holds too%s", parts[j].path, "");
	}
	const split_info *f = &parts[0].info;
	int64_t *sums = calloc((size_t)f->width * f->height * 4, sizeof *sums);
	int rc = !sums || add_parts(parts, n, sums) || write_image(out, &parts[0], sums) ? -1 : 0;
	free(sums);
	return rc;
}

int merge_main(int argc, char **argv)
{
	const char *out = NULL;
	int quiet = 0, n = 0;
	struct part *parts = calloc((size_t)argc, sizeof *parts);
	if (!parts)
		return 1;
	for (int i = 1; i < argc; i++) {
		if ((strcmp(argv[i], "-o") == 0 || strcmp(argv[i], "--output") == 0) && i + 1 < argc)
			out = argv[++i];
		else if (strncmp(argv[i], "--output=", 9) == 0)
			out = argv[i] + 9;
		else if (strcmp(argv[i], "-q") == 0 || strcmp(argv[i], "--quiet") == 0)
			quiet = 1;
		else if (strcmp(argv[i], "-h") == 0 || strcmp(argv[i], "--help") == 0) {
			usage(stdout);
			free(parts);
			return 0;
		} else if (argv[i][0] == '-' && argv[i][1]) {
			fprintf(stderr, "eclat: merge: unknown option '%s'\n", argv[i]);
			n = -1;
			break;
		} else
			parts[n++].path = argv[i];
	}
	int rc = 1;
	if (n > 0 && out && !image_format_known(out))
		fprintf(stderr, "eclat: merge: cannot write '%s': unknown image format\n", out);
	else if (n > 0 && out)
		rc = merge(parts, n, out) ? 1 : 0;
	else
		usage(stderr);
	if (rc == 0 && !quiet)
		fprintf(stderr, "eclat: merged %d parts into '%s', %ld samples a pixel\n", n, out, parts[0].info.total);
	for (int i = 0; i < (n > 0 ? n : 0); i++) {
		split_info_free(&parts[i].info);
		free(parts[i].sums);
	}
	free(parts);
	return rc;
}
