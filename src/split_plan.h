/* split_plan.h: what a render asked to split (--sample-range, a region) or to
 * resume (--resume, --continue) renders, and the EXR it writes (src/split.h). */
#ifndef ECLAT_SPLIT_PLAN_H
#define ECLAT_SPLIT_PLAN_H

#include "film.h"
#include "render.h"
#include "split.h"

typedef struct {
	const char *scene, *output;
	const char *resume;            /* --resume FILE, or NULL */
	int resume_output;             /* --continue (POV-Ray's +C): resume from output when it is there */
	int range_first, range_count;  /* --sample-range; count 0: every sample */
	const int *part;               /* the region (CLI_REGION_ order: left, top, right, bottom), or NULL */
	int n_aovs;                    /* AOVs do not merge: a sample range may not write them */
	const char *options;           /* the options that change pixels, "name=value\n" lines */
	float gamma;                   /* the scene's working gamma */
	const split_inputs *inputs;    /* the files the scene read */
} split_request;

/* 1 when path names an EXR, which keeps the film's sums. */
int split_is_exr(const char *path);

/* Sets rs's sample range, rows and (resuming) starting sums, which *resumed
 * holds (free() it after the render), and info, the record the output keeps
 * when it is an EXR. rs->samples is the whole render's samples on entry.
 * Returns 0, or -1 after saying what is wrong. */
int split_plan(const split_request *rq, render_settings *rs, split_info *info, int64_t **resumed);

/* Writes the film as info's EXR: rgb and the sums of the pixels of info's
 * region (the rows of a region hold some outside it). */
int split_write_film(const film *f, const float *rgb, split_info *info, const char *path, char *err, size_t n);

#endif
