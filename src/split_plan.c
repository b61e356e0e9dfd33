/* split_plan.c: a render's part of a split render (its samples and rows), the
 * render it resumes, and the EXR of its sums. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <unistd.h>

#include "diag.h"
#include "split_plan.h"

int split_is_exr(const char *path)
{
	const char *dot = strrchr(path, '.');
	return dot && strcasecmp(dot, ".exr") == 0;
}

int split_write_film(const film *f, const float *rgb, split_info *info, const char *path, char *err, size_t n)
{
	size_t npix = (size_t)f->width * f->height;
	int64_t *sums = malloc(npix * 4 * sizeof *sums);
	if (!sums) {
		snprintf(err, n, "out of memory");
		return -1;
	}
	for (size_t i = 0; i < npix; i++)
		for (int c = 0; c < 4; c++)
			sums[4 * i + c] = split_in_region(info, (int)(i % f->width), (int)(i / f->width)) ? f->sums[4 * i + c] : 0;
	info->samples = f->samples;
	int rc = split_write(path, rgb, sums, info, err, n);
	free(sums);
	return rc;
}

/* --resume FILE (or --continue's output): the sums of the samples it holds, if
 * it is this render's. */
static int resume_from(const char *path, const split_info *now, render_settings *rs, int64_t **sums)
{
	split_info was;
	char why[1024];
	const char *problem = why;
	int rc = -1;
	if (split_read(path, &was, sums, why, sizeof why))
		problem = why;
	else if (split_key_diff(&was.key, &now->key, why, sizeof why))
		problem = why;
	else if (was.first != now->first || memcmp(was.region, now->region, sizeof was.region) != 0)
		problem = "it holds another sample range or region than the one asked for";
	else if (was.samples > now->count)
		problem = "it holds more samples than asked for";
	else {
		rs->start_sums = *sums;
		rs->start_samples = was.samples;
		rc = 0;
	}
	if (rc)
		fprintf(stderr, "eclat: cannot resume from '%s': %s\n", path, problem);
	split_info_free(&was);
	return rc;
}

/* --continue: the output, when it is there and can be resumed. */
static const char *resume_file(const split_request *rq)
{
	if (rq->resume || !rq->resume_output || access(rq->output, F_OK) != 0)
		return rq->resume;
	if (split_is_exr(rq->output))
		return rq->output;
	diag_warning(SRC_NOWHERE, "+C: eclat continues only from an EXR; rendering '%s' again", rq->output);
	return NULL;
}

int split_plan(const split_request *rq, render_settings *rs, split_info *info, int64_t **resumed)
{
	long total = rs->samples;
	const char *resume = resume_file(rq);
	int exr = split_is_exr(rq->output);
	if (rq->range_count && (rq->range_first + (long)rq->range_count > total || !exr || rq->n_aovs)) {
		fprintf(stderr, "eclat: --sample-range %d:%d %s\n", rq->range_first, rq->range_count,
		        rq->n_aovs ? "cannot write AOVs: they do not merge"
		        : !exr ? "writes an EXR for 'eclat merge': name one with -o PART.exr"
		        : "reaches past the render's samples (-s, or 1 for whitted)");
		return -1;
	}
	*info = (split_info){ .scene = (char *)rq->scene, .width = rs->width, .height = rs->height, .total = total,
	                      .first = rq->range_count ? rq->range_first : 0, .gamma = rq->gamma,
	                      .region = { 0, 0, rs->width - 1, rs->height - 1 } };
	info->count = rq->range_count ? rq->range_count : total;
	if (rq->part) {
		memcpy(info->region, rq->part, sizeof info->region);
		rs->row_first = rq->part[1];
		rs->rows = rq->part[3] - rq->part[1] + 1;
	}
	rs->sample_first = (int)info->first;
	rs->samples = (int)info->count;
	int rc = exr || resume ? split_key_make(&info->key, rq->scene, rq->inputs, rq->options) : 0;
	if (rc == 0 && resume)
		rc = resume_from(resume, info, rs, resumed);
	return rc;
}
