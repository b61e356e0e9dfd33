/* cli_pov.c: POV-Ray 3.7's switches and INI keys, turned into eclat's options.
 *
 * Both spellings of a setting lead to one kind (ORDER of no table matters but
 * the switches', below); a kind either becomes one of eclat's long options or
 * lands in the cli_pov. Where eclat cannot do what is asked, one warning says
 * so and the render goes on; only what POV-Ray itself would refuse, or a
 * shell command, is an error. An unknown key in an INI file, which POV-Ray
 * refuses too, is only a warning, so that an INI file written for another
 * POV-Ray still renders. */
#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "cli_pov.h"

struct cli_args {
	cli_pov *pov;
	char **v;
	int n, cap;
};

enum kind {
	K_SILENT,     /* nothing to do in eclat: a display, log or memory knob */
	K_WARN,       /* eclat cannot do it: a warning */
	K_AA_WARN,    /* anti-aliasing's details that eclat has not: a warning */
	K_AA_METHOD, K_AA_DEPTH, K_AA_GAMMA, K_JITTER, K_JITTER_AMOUNT,   /* the whitted integrator's anti-aliasing */
	K_WIDTH, K_HEIGHT, K_INPUT, K_OUTPUT, K_TO_FILE, K_TYPE, K_BITS, K_ALPHA,
	K_AA, K_AA_THRESHOLD, K_QUALITY, K_LIBRARY, K_DECLARE, K_DISPLAY, K_PAUSE, K_THREADS, K_SEED,
	K_LEFT, K_TOP, K_RIGHT, K_BOTTOM,   /* ORDER CLI_REGION_ */
	K_CONTINUE, K_CLOCK, K_INITIAL_FRAME, K_FINAL_FRAME, K_INITIAL_CLOCK, K_FINAL_CLOCK,
	K_SUBSET_START, K_SUBSET_END, K_FRAME_STEP, K_CYCLIC, K_SHELL, K_INCLUDE_INI,
};

enum { P_NONE, P_OPTIONAL, P_REQUIRED };   /* a switch's parameter */

/* POV-Ray's switches in its own order (processrenderoptions.cpp): the first
 * whose letters begin the switch, in any case, is the one. ORDER MATTERS. */
static const struct pov_switch {
	const char *name;
	enum kind kind;
	int param;
	const char *what;   /* for a warning */
} switches[] = {
	{ "AC", K_AA_WARN, P_REQUIRED, "anti-aliasing confidence" },
	{ "AG", K_AA_GAMMA, P_REQUIRED, NULL },
	{ "AM", K_AA_METHOD, P_REQUIRED, NULL },
	{ "A", K_AA, P_OPTIONAL, NULL },
	{ "BM", K_SILENT, P_REQUIRED, NULL },
	{ "BS", K_SILENT, P_REQUIRED, NULL },
	{ "B", K_SILENT, P_NONE, NULL },
	{ "CC", K_WARN, P_NONE, "continue-trace log" },
	{ "C", K_CONTINUE, P_NONE, NULL },
	{ "D", K_DISPLAY, P_OPTIONAL, NULL },
	{ "EC", K_RIGHT, P_REQUIRED, NULL },
	{ "EF0", K_SUBSET_END, P_REQUIRED, NULL },
	{ "EF", K_SUBSET_END, P_REQUIRED, NULL },
	{ "EP", K_SILENT, P_REQUIRED, NULL },
	{ "ER", K_BOTTOM, P_REQUIRED, NULL },
	{ "F", K_TYPE, P_OPTIONAL, NULL },
	{ "GA", K_SILENT, P_OPTIONAL, NULL },
	{ "GD", K_SILENT, P_OPTIONAL, NULL },
	{ "GF", K_SILENT, P_OPTIONAL, NULL },
	{ "GI", K_WARN, P_REQUIRED, "writing the settings as an INI file" },
	{ "GP", K_SILENT, P_NONE, NULL },
	{ "GR", K_SILENT, P_OPTIONAL, NULL },
	{ "GS", K_SILENT, P_OPTIONAL, NULL },
	{ "GW", K_SILENT, P_OPTIONAL, NULL },
	{ "HI", K_WARN, P_REQUIRED, "an include header" },
	{ "HR", K_SILENT, P_NONE, NULL },
	{ "H", K_HEIGHT, P_REQUIRED, NULL },
	{ "I", K_INPUT, P_REQUIRED, NULL },
	{ "J", K_JITTER, P_OPTIONAL, NULL },
	{ "KC", K_CYCLIC, P_NONE, NULL },
	{ "KI", K_INITIAL_CLOCK, P_REQUIRED, NULL },
	{ "KFF", K_FINAL_FRAME, P_REQUIRED, NULL },
	{ "KFI", K_INITIAL_FRAME, P_REQUIRED, NULL },
	{ "KF", K_FINAL_CLOCK, P_REQUIRED, NULL },
	{ "KLA", K_WARN, P_NONE, "clockless animation" },
	{ "K", K_CLOCK, P_REQUIRED, NULL },
	{ "L", K_LIBRARY, P_REQUIRED, NULL },
	{ "MB", K_SILENT, P_OPTIONAL, NULL },
	{ "MI", K_WARN, P_REQUIRED, "an image buffer memory limit" },
	{ "MV", K_WARN, P_REQUIRED, "a language version switch (#version in the scene is)" },
	{ "O", K_OUTPUT, P_REQUIRED, NULL },
	{ "P", K_PAUSE, P_NONE, NULL },
	{ "Q", K_QUALITY, P_REQUIRED, NULL },
	{ "RFI", K_WARN, P_NONE, "radiosity data from a file" },
	{ "RFO", K_WARN, P_NONE, "radiosity data to a file" },
	{ "RF", K_WARN, P_REQUIRED, "a radiosity file" },
	{ "RS", K_SILENT, P_REQUIRED, NULL },
	{ "RP", K_SILENT, P_REQUIRED, NULL },
	{ "RTR", K_WARN, P_NONE, "real-time ray tracing" },
	{ "RVP", K_WARN, P_NONE, "radiosity's vain pretrace" },
	{ "R", K_AA_DEPTH, P_REQUIRED, NULL },
	{ "SC", K_LEFT, P_REQUIRED, NULL },
	{ "SF0", K_SUBSET_START, P_REQUIRED, NULL },
	{ "SF", K_SUBSET_START, P_REQUIRED, NULL },
	{ "SP", K_SILENT, P_REQUIRED, NULL },
	{ "SR", K_TOP, P_REQUIRED, NULL },
	{ "SS", K_SEED, P_REQUIRED, NULL },
	{ "STP", K_FRAME_STEP, P_REQUIRED, NULL },
	{ "SU", K_SILENT, P_NONE, NULL },
	{ "TH", K_WARN, P_OPTIONAL, "dithering" },
	{ "UA", K_ALPHA, P_NONE, NULL },
	{ "UD", K_SILENT, P_NONE, NULL },
	{ "UF", K_WARN, P_NONE, "field rendering" },
	{ "UL", K_SILENT, P_NONE, NULL },
	{ "UO", K_WARN, P_NONE, "odd fields" },
	{ "UR", K_SILENT, P_NONE, NULL },
	{ "UV", K_SILENT, P_NONE, NULL },
	{ "V", K_SILENT, P_NONE, NULL },
	{ "WL", K_SILENT, P_REQUIRED, NULL },
	{ "WT", K_THREADS, P_REQUIRED, NULL },
	{ "W", K_WIDTH, P_REQUIRED, NULL },
	{ "X", K_SILENT, P_OPTIONAL, NULL },
};

/* POV-Ray's INI keys (its RenderOptions_INI_Table). bool: the value is on/off. */
static const struct pov_key {
	const char *name;
	enum kind kind;
	int is_bool;
	const char *what;
} keys[] = {
	{ "All_Console", K_SILENT, 1, NULL }, { "All_File", K_SILENT, 0, NULL },
	{ "Antialias", K_AA, 1, NULL }, { "Antialias_Confidence", K_AA_WARN, 0, "anti-aliasing confidence" },
	{ "Antialias_Depth", K_AA_DEPTH, 0, NULL },
	{ "Antialias_Gamma", K_AA_GAMMA, 0, NULL },
	{ "Antialias_Threshold", K_AA_THRESHOLD, 0, NULL }, { "Append_File", K_SILENT, 1, NULL },
	{ "Bits_Per_Color", K_BITS, 0, NULL }, { "Bits_Per_Colour", K_BITS, 0, NULL },
	{ "Bounding", K_SILENT, 1, NULL }, { "Bounding_Method", K_SILENT, 0, NULL },
	{ "Bounding_Threshold", K_SILENT, 0, NULL }, { "BSP_BaseAccessCost", K_SILENT, 0, NULL },
	{ "BSP_ChildAccessCost", K_SILENT, 0, NULL }, { "BSP_ISectCost", K_SILENT, 0, NULL },
	{ "BSP_MaxDepth", K_SILENT, 0, NULL }, { "BSP_MissChance", K_SILENT, 0, NULL },
	{ "Buffer_Output", K_SILENT, 0, NULL }, { "Buffer_Size", K_SILENT, 0, NULL },
	{ "Clock", K_CLOCK, 0, NULL }, { "Clockless_Animation", K_WARN, 1, "clockless animation" },
	{ "Compression", K_SILENT, 0, NULL }, { "Continue_Trace", K_CONTINUE, 1, NULL },
	{ "Create_Continue_Trace_Log", K_WARN, 1, "a continue-trace log" },
	{ "Create_Histogram", K_WARN, 1, "a histogram" }, { "Create_Ini", K_WARN, 0, "writing the settings as an INI file" },
	{ "Cyclic_Animation", K_CYCLIC, 1, NULL }, { "Debug_Console", K_SILENT, 1, NULL },
	{ "Debug_File", K_SILENT, 0, NULL }, { "Declare", K_DECLARE, 0, NULL },
	{ "Display", K_DISPLAY, 1, NULL }, { "Display_Gamma", K_SILENT, 0, NULL },
	{ "Dither", K_WARN, 1, "dithering" }, { "Dither_Method", K_WARN, 0, "dithering" },
	{ "Draw_Vistas", K_SILENT, 1, NULL }, { "End_Column", K_RIGHT, 0, NULL }, { "End_Row", K_BOTTOM, 0, NULL },
	{ "Fatal_Console", K_SILENT, 1, NULL }, { "Fatal_Error_Command", K_SHELL, 0, NULL },
	{ "Fatal_Error_Return", K_SILENT, 0, NULL }, { "Fatal_File", K_SILENT, 0, NULL },
	{ "Field_Render", K_WARN, 1, "field rendering" }, { "File_Gamma", K_WARN, 0, "a file gamma other than sRGB's" },
	{ "Final_Clock", K_FINAL_CLOCK, 0, NULL }, { "Final_Frame", K_FINAL_FRAME, 0, NULL },
	{ "Frame_Step", K_FRAME_STEP, 0, NULL }, { "Grayscale_Output", K_WARN, 1, "grey output" },
	{ "Greyscale_Output", K_WARN, 1, "grey output" }, { "Height", K_HEIGHT, 0, NULL },
	{ "High_Reproducibility", K_SILENT, 1, NULL }, { "Histogram_Name", K_WARN, 0, "a histogram" },
	{ "Histogram_Grid_Size", K_WARN, 0, "a histogram" }, { "Histogram_Type", K_WARN, 0, "a histogram" },
	{ "Initial_Clock", K_INITIAL_CLOCK, 0, NULL }, { "Initial_Frame", K_INITIAL_FRAME, 0, NULL },
	{ "Input_File_Name", K_INPUT, 0, NULL }, { "Include_Header", K_WARN, 0, "an include header" },
	{ "Include_Ini", K_INCLUDE_INI, 0, NULL }, { "Jitter_Amount", K_JITTER_AMOUNT, 0, NULL },
	{ "Jitter", K_JITTER, 1, NULL }, { "Library_Path", K_LIBRARY, 0, NULL },
	{ "Light_Buffer", K_SILENT, 1, NULL }, { "Max_Image_Buffer_Memory", K_WARN, 0, "an image buffer memory limit" },
	{ "Odd_Field", K_WARN, 1, "odd fields" }, { "Output_Alpha", K_ALPHA, 1, NULL },
	{ "Output_File_Name", K_OUTPUT, 0, NULL }, { "Output_File_Type", K_TYPE, 0, NULL },
	{ "Output_To_File", K_TO_FILE, 1, NULL }, { "Palette", K_SILENT, 0, NULL },
	{ "Pause_When_Done", K_PAUSE, 1, NULL }, { "Post_Frame_Command", K_SHELL, 0, NULL },
	{ "Post_Frame_Return", K_SILENT, 0, NULL }, { "Post_Scene_Command", K_SHELL, 0, NULL },
	{ "Post_Scene_Return", K_SILENT, 0, NULL }, { "Preview_End_Size", K_SILENT, 0, NULL },
	{ "Preview_Start_Size", K_SILENT, 0, NULL }, { "Pre_Frame_Command", K_SHELL, 0, NULL },
	{ "Pre_Frame_Return", K_SILENT, 0, NULL }, { "Pre_Scene_Command", K_SHELL, 0, NULL },
	{ "Pre_Scene_Return", K_SILENT, 0, NULL }, { "Quality", K_QUALITY, 0, NULL },
	{ "Radiosity_File_Name", K_WARN, 0, "a radiosity file" },
	{ "Radiosity_From_File", K_WARN, 1, "radiosity data from a file" },
	{ "Radiosity_To_File", K_WARN, 1, "radiosity data to a file" },
	{ "Radiosity_Vain_Pretrace", K_WARN, 1, "radiosity's vain pretrace" },
	{ "Real_Time_Raytracing", K_WARN, 1, "real-time ray tracing" }, { "Remove_Bounds", K_SILENT, 1, NULL },
	{ "Render_Block_Size", K_SILENT, 0, NULL }, { "Render_Block_Step", K_SILENT, 0, NULL },
	{ "Render_Console", K_SILENT, 1, NULL }, { "Render_File", K_SILENT, 0, NULL },
	{ "Render_Pattern", K_SILENT, 0, NULL }, { "Sampling_Method", K_AA_METHOD, 0, NULL },
	{ "Split_Unions", K_SILENT, 1, NULL }, { "Start_Column", K_LEFT, 0, NULL },
	{ "Start_Row", K_TOP, 0, NULL }, { "Statistic_Console", K_SILENT, 1, NULL },
	{ "Statistic_File", K_SILENT, 0, NULL }, { "Stochastic_Seed", K_SEED, 0, NULL },
	{ "Subset_End_Frame", K_SUBSET_END, 0, NULL }, { "Subset_Start_Frame", K_SUBSET_START, 0, NULL },
	{ "Test_Abort_Count", K_SILENT, 0, NULL }, { "Test_Abort", K_SILENT, 1, NULL },
	{ "User_Abort_Command", K_SHELL, 0, NULL }, { "User_Abort_Return", K_SILENT, 0, NULL },
	{ "Verbose", K_SILENT, 1, NULL }, { "Version", K_WARN, 0, "a language version switch (#version in the scene is)" },
	{ "Video_Mode", K_SILENT, 0, NULL }, { "Vista_Buffer", K_SILENT, 1, NULL },
	{ "Warning_Console", K_SILENT, 1, NULL }, { "Warning_File", K_SILENT, 0, NULL },
	{ "Warning_Level", K_SILENT, 0, NULL }, { "Width", K_WIDTH, 0, NULL },
	{ "Work_Threads", K_THREADS, 0, NULL },
};

#define COUNT(a) (sizeof(a) / sizeof *(a))

/* One setting as it arrived: its spelling for messages ("+W" or "Width") and
 * where its value is. */
struct setting {
	const char *name;
	int on;              /* a switch's + (1) or - (0); an INI boolean's value */
	const char *value;   /* NULL: none */
	src_loc loc;         /* the value's place in an INI file, or SRC_NOWHERE */
};

/* What the arguments became lives until exit, like argv itself: kept here, so
 * that a leak checker sees it reachable. */
static char **kept;
static size_t n_kept, cap_kept;
/* The argument vector being built: kept only once complete, so a diag_exit(1)
 * halfway leaves it here. */
static char **building;

char *cli_pov_keep(char *s)
{
	if (s && n_kept == cap_kept) {
		cap_kept = cap_kept ? 2 * cap_kept : 64;
		char **k = realloc(kept, cap_kept * sizeof *k);
		if (!k)
			s = NULL;
		else
			kept = k;
	}
	if (!s) {
		fprintf(stderr, "eclat: out of memory\n");
		diag_exit(1);
	}
	return kept[n_kept++] = s;
}

void cli_pov_release(void)
{
	for (size_t i = 0; i < n_kept; i++)
		free(kept[i]);
	free(kept);
	free(building);
	kept = NULL;
	building = NULL;
	n_kept = cap_kept = 0;
}

static void push(cli_args *a, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

static void push(cli_args *a, const char *fmt, ...)
{
	if (a->n + 2 > a->cap) {
		a->cap = a->cap ? 2 * a->cap : 32;
		a->v = realloc(a->v, (size_t)a->cap * sizeof *a->v);
		building = a->v;
	}
	va_list ap;
	va_start(ap, fmt);
	char *s = NULL;
	if (!a->v || vasprintf(&s, fmt, ap) < 0) {
		fprintf(stderr, "eclat: out of memory\n");
		diag_exit(1);
	}
	va_end(ap);
	a->v[a->n++] = cli_pov_keep(s);
	a->v[a->n] = NULL;
}

/* A bad argument ends the run before anything is read or rendered. */
#define FAIL(loc, ...) do { diag_error((loc), __VA_ARGS__); diag_exit(1); } while (0)

static long whole(const struct setting *s, long lo, long hi)
{
	char *end;
	errno = 0;
	long v = s->value ? strtol(s->value, &end, 10) : 0;
	if (!s->value || errno || end == s->value || *end || v < lo || v > hi)
		FAIL(s->loc, "%s needs a whole number from %ld to %ld, not '%s'", s->name, lo, hi,
		     s->value ? s->value : "");
	return v;
}

static double number(const struct setting *s)
{
	char *end;
	errno = 0;
	double v = s->value ? strtod(s->value, &end) : 0;
	if (!s->value || errno || end == s->value || *end || !isfinite(v))
		FAIL(s->loc, "%s needs a number, not '%s'", s->name, s->value ? s->value : "");
	return v;
}

/* Subset_Start_Frame=0.5 or +SF0.5: a fraction of the animation, as in POV-Ray;
 * a whole number is a frame. Kept as it is: negative for a fraction. */
static double subset(const struct setting *s)
{
	double v = number(s);
	if (v < 0)
		FAIL(s->loc, "%s needs a frame number or a fraction from 0 to 1, not '%s'", s->name, s->value);
	return v < 1 && strchr(s->value, '.') ? -1 - v : v;
}

/* +FN16, +FE, Output_File_Type=N: POV-Ray's letters for eclat's formats. */
static void file_type(cli_pov *p, const struct setting *s)
{
	const char *v = s->value;
	if (!v || !*v) {   /* +F alone: output on, the type as before; -F: no output */
		if (!s->on)
			diag_warning(s->loc, "%s: eclat always writes the image", s->name);
		return;
	}
	char t = (char)toupper((unsigned char)*v++);
	if (!strchr("NEHTCPJB", t)) {
		if (strchr("S", t))
			FAIL(s->loc, "%s%c: eclat has no system image type; use N (PNG), E (OpenEXR), H (HDR), "
			     "T (Targa), P (PPM), J (JPEG) or B (BMP)", s->name, t);
		FAIL(s->loc, "unknown output file type '%c' in %s (POV-Ray's are N, E, H, T, C, P, J, B)", t, s->name);
	}
	p->file_type = t;
	p->bits = 0;
	if (toupper((unsigned char)*v) == 'G') {
		diag_warning(s->loc, "%s: grey output is not there yet; the image is in colour", s->name);
		v++;
	}
	if (*v) {
		struct setting b = { s->name, 1, v, s->loc };
		p->bits = (int)whole(&b, 1, 16);
	}
}

static void animation(cli_pov *p, enum kind k, const struct setting *s)
{
	switch (k) {
	case K_CLOCK: p->clock = number(s); p->clock_given = 1; break;
	case K_INITIAL_FRAME: p->initial_frame = whole(s, -1000000000, 1000000000); p->anim |= 1; break;
	case K_FINAL_FRAME: p->final_frame = whole(s, -1000000000, 1000000000); p->anim |= 2; break;
	case K_INITIAL_CLOCK: p->initial_clock = number(s); break;
	case K_FINAL_CLOCK: p->final_clock = number(s); break;
	case K_SUBSET_START: p->subset_start = subset(s); p->subset_start_given = 1; break;
	case K_SUBSET_END: p->subset_end = subset(s); p->subset_end_given = 1; break;
	case K_FRAME_STEP: p->frame_step = whole(s, -1000000000, 1000000000); break;   /* POV-Ray: below 1 is 1 */
	default: p->cyclic = s->on; break;
	}
}

static void shell_refused(const struct setting *s, src_loc key_loc)
{
	FAIL(key_loc, "%s runs a shell command: eclat does not allow shell-outs from INI files or the command line",
	     s->name);
}

/* A setting that is only ever a warning, or nothing. */
static void warn_or_not(enum kind k, const struct setting *s, const char *what)
{
	if (k == K_WARN && s->on)
		diag_warning(s->loc, "%s (%s): not in eclat; ignored", s->name, what);
	else if (k == K_AA_WARN)
		diag_warning(s->loc, "%s (%s): ignored; eclat's anti-aliasing methods are 1 and 2", s->name, what);
}

/* The whitted integrator's anti-aliasing, clipped to POV-Ray 3.7's ranges as
 * its View::StartRender clips them (the threshold too, where it is used). */
static void antialiasing(cli_pov *p, enum kind k, const struct setting *s)
{
	switch (k) {
	case K_AA_METHOD:
		p->aa_method = (int)whole(s, 0, 3);
		if (p->aa_method == 3) {
			diag_warning(s->loc, "%s3: POV-Ray 3.7 has no method 3; eclat uses method 2", s->name);
			p->aa_method = 2;
		}
		break;
	case K_AA_DEPTH:   /* POV-Ray clips it to 1 .. 9 */
		p->aa_depth = (int)whole(s, -1000000000, 1000000000);
		p->aa_depth = p->aa_depth < 1 ? 1 : p->aa_depth > 9 ? 9 : p->aa_depth;
		break;
	case K_AA_GAMMA: p->aa_gamma = number(s); break;
	case K_JITTER:   /* +J0.5 is Jitter on with Jitter_Amount 0.5 */
		p->jitter = s->on;
		if (s->value && *s->value)
			p->jitter_amount = number(s);
		break;
	default: p->jitter_amount = number(s); break;
	}
}

static void apply(cli_args *a, enum kind k, const struct setting *s, src_loc key_loc, const char *what)
{
	cli_pov *p = a->pov;
	switch (k) {
	case K_SILENT: break;
	case K_WARN: case K_AA_WARN: warn_or_not(k, s, what); break;
	case K_WIDTH: push(a, "--width=%ld", whole(s, 1, 32768)); break;
	case K_HEIGHT: push(a, "--height=%ld", whole(s, 1, 32768)); break;
	case K_INPUT: p->scene = s->value; break;
	case K_OUTPUT: push(a, "--output=%s", s->value); break;
	case K_TO_FILE: if (!s->on) diag_warning(s->loc, "%s: eclat always writes the image", s->name); break;
	case K_TYPE: file_type(p, s); break;
	case K_BITS: p->bits = (int)whole(s, 1, 16); break;
	case K_ALPHA: p->alpha = s->on; break;
	case K_AA:
		if (s->value && *s->value)
			p->aa_threshold = number(s);
		p->antialias = s->on;
		break;
	case K_AA_THRESHOLD: p->aa_threshold = number(s); break;
	case K_AA_METHOD: case K_AA_DEPTH: case K_AA_GAMMA: case K_JITTER: case K_JITTER_AMOUNT:
		antialiasing(p, k, s);
		break;
	case K_QUALITY:
		if (whole(s, 0, 11) < 9)
			diag_warning(s->loc, "%s asks for quality %s; eclat draws the whole scene at any quality "
			             "(POV-Ray's 9 and up)", s->name, s->value);
		break;
	case K_LIBRARY: push(a, "--include-path=%s", s->value); break;
	case K_DECLARE: push(a, "--declare=%s", s->value); break;
	case K_DISPLAY: push(a, s->on ? "--preview" : "--no-preview"); break;   /* +D's palette letter is moot */
	case K_PAUSE: push(a, s->on ? "--pause" : "--no-pause"); break;
	case K_THREADS: push(a, "--threads=%ld", whole(s, 1, 512)); break;
	case K_SEED: push(a, "--seed=%ld", whole(s, 0, 2147483647)); break;
	case K_LEFT: case K_TOP: case K_RIGHT: case K_BOTTOM:
		p->region[k - K_LEFT] = number(s);
		p->region_given |= 1 << (k - K_LEFT);
		if (p->region[k - K_LEFT] < 0)
			FAIL(s->loc, "%s needs a fraction of the image or a pixel number, not '%s'", s->name, s->value);
		break;
	case K_CONTINUE:
		if (s->on)
			push(a, "--continue");
		break;
	case K_SHELL: shell_refused(s, key_loc); break;
	case K_INCLUDE_INI: cli_ini_read(a, s->value, s->loc); break;
	default: animation(p, k, s); break;
	}
}

/* "+W320": the sign, then the first switch of the table whose letters begin it. */
void cli_pov_switch(cli_args *a, const char *sw, src_loc loc)
{
	const char *body = sw + 1;
	for (size_t i = 0; i < COUNT(switches); i++) {
		const struct pov_switch *t = &switches[i];
		size_t n = strlen(t->name);
		if (strncasecmp(body, t->name, n) != 0)
			continue;
		const char *param = body + n;
		char name[8];
		snprintf(name, sizeof name, "%c%s", sw[0], t->name);
		/* +SF0.5 and +EF0.5 match SF0 and EF0, whose value starts at the 0 */
		if (t->name[n - 1] == '0')
			param--;
		if (t->param == P_NONE && *param)
			FAIL(loc, "POV-Ray's %s takes no value: '%s'", name, sw);
		if (t->param == P_REQUIRED && !*param)
			FAIL(loc, "POV-Ray's %s needs a value: '%s'", name, sw);
		struct setting s = { name, sw[0] == '+', *param ? param : NULL, loc };
		apply(a, t->kind, &s, loc, t->what);
		return;
	}
	FAIL(loc, "unknown switch '%s' (POV-Ray has no such switch)", sw);
}

static const struct pov_key *find_key(const char *key)
{
	for (size_t i = 0; i < COUNT(keys); i++)
		if (strcasecmp(keys[i].name, key) == 0)
			return &keys[i];
	return NULL;
}

static int boolean(const char *v, int *on)
{
	static const char *const yes[] = { "on", "true", "yes", "1" }, *const no[] = { "off", "false", "no", "0" };
	for (int i = 0; i < 4; i++) {
		if (strcasecmp(v, yes[i]) == 0)
			return *on = 1, 0;
		if (strcasecmp(v, no[i]) == 0)
			return *on = 0, 0;
	}
	return -1;
}

/* Width=320 (from an INI file or the command line). */
void cli_pov_setting(cli_args *a, const char *key, const char *value, src_loc key_loc, src_loc value_loc)
{
	const struct pov_key *k = find_key(key);
	if (!k) {
		if (key_loc.file >= 0)
			diag_warning(key_loc, "unknown INI key '%s' (not one of POV-Ray's); ignored", key);
		else
			FAIL(key_loc, "unknown POV-Ray INI key '%s' in '%s=%s'", key, key, value);
		return;
	}
	struct setting s = { k->name, 1, value, value_loc };
	if (k->kind == K_SHELL)
		shell_refused(&s, key_loc);
	if (k->is_bool) {
		if (boolean(value, &s.on))
			FAIL(value_loc, "%s needs on, off, true, false, yes, no, 1 or 0, not '%s'", k->name, value);
		s.value = NULL;
	} else if (!*value && k->kind != K_SILENT && k->kind != K_WARN) {
		FAIL(value_loc, "%s needs a value", k->name);
	}
	apply(a, k->kind, &s, key_loc, k->what);
}

/* A scene named plainly, or an INI file. */
void cli_pov_plain(cli_args *a, const char *arg, src_loc loc)
{
	if (cli_ini_named(arg)) {
		cli_ini_read(a, arg, loc);
		return;
	}
	a->pov->scene = arg;
	if (loc.file < 0)
		a->pov->n_plain_scenes++;
}

/* The long option arg names ("--output" or a unique start of one), or NULL. */
static const struct option *long_option(const struct option *longopts, const char *arg)
{
	size_t n = strcspn(arg + 2, "=");
	const struct option *found = NULL;
	for (const struct option *o = longopts; o->name; o++) {
		if (strncmp(o->name, arg + 2, n) != 0)
			continue;
		if (o->name[n] == '\0')
			return o;
		found = found ? NULL : o;   /* ambiguous: getopt_long says so */
	}
	return found;
}

static int is_identifier(const char *s, size_t n)
{
	if (n == 0 || !(isalpha((unsigned char)s[0]) || s[0] == '_'))
		return 0;
	for (size_t i = 1; i < n; i++)
		if (!(isalnum((unsigned char)s[i]) || s[i] == '_'))
			return 0;
	return 1;
}

/* NAME=VALUE where NAME is not one of POV-Ray's INI keys: eclat's declaration. */
static int is_declaration(const char *s)
{
	size_t n = strcspn(s, "=");
	if (!s[n] || n == 0)
		return 0;
	char key[64];
	snprintf(key, sizeof key, "%.*s", (int)(n < 63 ? n : 63), s);
	return !find_key(key);
}

/* POV-Ray's -D and eclat's -D: the display switch unless a declaration
 * (NAME=VALUE) is attached or follows as a separate argument. Returns how many
 * arguments it used. */
static int dash_d(cli_args *a, char **argv, int i, int argc)
{
	const char *arg = argv[i];
	if (arg[2] && strchr(arg + 2, '=')) {
		push(a, "--declare=%s", arg + 2);
		return 1;
	}
	if (!arg[2] && arg[0] == '-' && i + 1 < argc && is_declaration(argv[i + 1]) &&
	    argv[i + 1][0] != '-' && argv[i + 1][0] != '+') {
		push(a, "--declare=%s", argv[i + 1]);
		return 2;
	}
	if (!arg[2] && i + 1 < argc)
		a->pov->after_display = argv[i + 1];
	cli_pov_switch(a, arg, SRC_NOWHERE);
	return 1;
}

/* An argument that begins with '-' and one of eclat's own short options is
 * eclat's, but for -D (above), -V among other arguments (POV-Ray's verbose
 * off), -s followed by a letter (POV-Ray's -SR and the like), and -q or -h
 * with something attached (POV-Ray's -Q9, -H240: eclat's take nothing).
 * Returns how many arguments it used, 0 when it is not eclat's. */
static int eclat_short(cli_args *a, char **argv, int i, int argc, const char *shortopts)
{
	const char *arg = argv[i];
	const char *o = strchr(shortopts, arg[1]);
	if (!o || arg[1] == ':' || arg[1] == 'D' || (arg[1] == 'V' && argc > 2) ||
	    (arg[1] == 's' && isalpha((unsigned char)arg[2])) || ((arg[1] == 'q' || arg[1] == 'h') && arg[2]))
		return 0;
	push(a, "%s", arg);
	if (o[1] == ':' && !arg[2] && i + 1 < argc) {
		push(a, "%s", argv[i + 1]);
		return 2;
	}
	return 1;
}

static int one_argument(cli_args *a, char **argv, int i, int argc, const struct option *longopts,
                        const char *shortopts)
{
	const char *arg = argv[i];
	if (arg[0] == '-' && arg[1] == '-' && arg[2]) {
		push(a, "%s", arg);
		const struct option *o = long_option(longopts, arg);
		if (o && o->has_arg == required_argument && !strchr(arg, '=') && i + 1 < argc) {
			push(a, "%s", argv[i + 1]);
			return 2;
		}
		return 1;
	}
	if (strcmp(arg, "-version") == 0 || strcmp(arg, "-help") == 0) {   /* povray's own spellings */
		push(a, "-%s", arg);
		return 1;
	}
	if (arg[0] == '-' && (arg[1] == 'D' || arg[1] == 'd'))
		return dash_d(a, argv, i, argc);
	if (arg[0] == '-' && arg[1]) {
		int used = eclat_short(a, argv, i, argc, shortopts);
		if (used)
			return used;
	}
	if ((arg[0] == '-' || arg[0] == '+') && arg[1]) {
		cli_pov_switch(a, arg, SRC_NOWHERE);
		return 1;
	}
	size_t n = strcspn(arg, "=");
	if (arg[n] && is_identifier(arg, n)) {   /* Width=320, Declare=R=2 */
		cli_pov_setting(a, cli_pov_keep(strndup(arg, n)), arg + n + 1, SRC_NOWHERE, SRC_NOWHERE);
		return 1;
	}
	cli_pov_plain(a, arg, SRC_NOWHERE);
	return 1;
}

int cli_pov_args(int argc, char **argv, const struct option *longopts, const char *shortopts,
                 cli_pov *pov, char ***out)
{
	*pov = (cli_pov){ .antialias = -1, .initial_frame = 1, .final_frame = 1, .final_clock = 1,
	                  .aa_method = 1, .aa_threshold = 0.3, .aa_depth = 3, .aa_gamma = 2.5, .jitter = 1,
	                  .jitter_amount = 1 };
	cli_args a = { .pov = pov };
	push(&a, "%s", argv[0]);
	/* POV-Ray reads the INI file $POVINI names before the command line. */
	const char *povini = getenv("POVINI");
	if (povini && *povini)
		cli_ini_read(&a, povini, SRC_NOWHERE);
	int i = 1;
	while (i < argc) {
		if (strcmp(argv[i], "--") == 0) {   /* the rest are scenes */
			for (i++; i < argc; i++) {
				pov->scene = argv[i];
				pov->n_plain_scenes++;
			}
			break;
		}
		i += one_argument(&a, argv, i, argc, longopts, shortopts);
	}
	*out = a.v;
	building = NULL;
	cli_pov_keep((char *)a.v);
	return a.n;
}

/* POV-Ray's reading of +SF and +EF (its animationprocessing.cpp): a fraction
 * counts frames from 0, not from the first frame, then is clamped. */
static long subset_frame(double v, long first, long last)
{
	double f = v >= 0 ? v : (double)(last - first + 1) * (-1 - v);
	/* clamped here as after, before a long could overflow */
	return !(f >= (double)first) ? first : f > (double)last ? last : (long)f;
}

void cli_pov_frame(const cli_pov *p, cli_frame *f)
{
	*f = (cli_frame){ .clock = p->clock, .clock_on = p->clock_given, .frames = 1, .step = 1 };
	if (!p->anim)
		return;
	long first = p->initial_frame < 0 ? 0 : p->initial_frame;
	/* a cyclic animation has one frame more, which it does not render: the
	 * clock's end is the first frame again */
	long last = (p->final_frame < first ? first : p->final_frame) + (p->cyclic ? 1 : 0);
	long from = first, to = last - (p->cyclic ? 1 : 0);
	if (p->subset_start_given)
		from = subset_frame(p->subset_start, first, last);
	if (p->subset_end_given)
		to = subset_frame(p->subset_end, first, last);
	from = from < first ? first : from;
	to = to > last ? last : to < from ? from : to;
	f->first = from;
	f->step = p->frame_step > 1 ? p->frame_step : 1;
	f->frames = (to - from) / f->step + 1;   /* from, from + step... up to to, as POV-Ray steps */
	f->initial_frame = first;
	f->final_frame = last;
	f->initial_clock = p->initial_clock;
	f->final_clock = p->final_clock;
	f->clock_on = 1;
	f->clock_delta = last > first ? (p->final_clock - p->initial_clock) / (double)(last - first) : 0;
	char digits[32];
	f->digits = snprintf(digits, sizeof digits, "%ld", last);
	cli_frame_goto(f, from);
}

void cli_frame_goto(cli_frame *f, long frame)
{
	if (!f->digits)   /* no frame range: the one frame, at +K's clock */
		return;
	f->frame = frame;
	f->clock = f->initial_clock + f->clock_delta * (double)(frame - f->initial_frame);
}

static const char *type_extension(char t)
{
	switch (t) {
	case 'E': return ".exr";
	case 'H': return ".hdr";
	case 'T': case 'C': return ".tga";
	case 'P': return ".ppm";
	case 'J': return ".jpg";
	case 'B': return ".bmp";
	default: return ".png";
	}
}

char *cli_pov_output(const cli_pov *p, const cli_frame *f, const char *scene, const char *output)
{
	int from_scene = !output || !*output || output[strlen(output) - 1] == '/';   /* +Ofolder/ */
	const char *path = from_scene ? scene : output, *name = strrchr(path, '/');
	name = name ? name + 1 : path;
	size_t dir_len = from_scene ? (output ? strlen(output) : 0) : (size_t)(name - path);
	const char *dot = strrchr(name, '.');
	if (dot == name)
		dot = NULL;
	size_t stem = dot ? (size_t)(dot - name) : strlen(name);
	/* the scene's extension gives way to the image's; an output's own is kept */
	const char *ext = from_scene || !dot ? type_extension(p->file_type) : dot;
	char frame[32] = "";
	if (f->digits)
		snprintf(frame, sizeof frame, "%0*ld", f->digits, f->frame);
	char *out = NULL;
	if (asprintf(&out, "%.*s%.*s%s%s", (int)dir_len, from_scene ? (output ? output : "") : path, (int)stem, name,
	             frame, ext) < 0)
		return NULL;
	return out;
}

/* POV-Ray's reading of the part (its view.cpp): a value from 0 up to 1 is a
 * fraction of the image (up to and including 1 for the ends), any other a pixel
 * counted from 1. */
int cli_pov_region(const cli_pov *p, int width, int height, int rect[4])
{
	static const char *const names[4] = { "+SC", "+SR", "+EC", "+ER" };   /* ORDER CLI_REGION_ */
	int size[4] = { width, height, width, height };
	for (int i = 0; i < 4; i++) {
		double v = p->region[i], r;
		if (!(p->region_given & 1 << i))
			r = i < 2 ? 0 : size[i] - 1;
		else if (v >= 0 && (i < 2 ? v < 1 : v <= 1))
			r = floor(size[i] * v) - (i < 2 ? 0 : 1);
		else
			r = floor(v - 1);
		/* checked as a double: a pixel such as 4e100 (or NaN) is no int */
		if (!(r < size[i])) {
			diag_error(SRC_NOWHERE, "%s: %g is past the image's %s (%d pixels)", names[i], v,
			           i % 2 ? "height" : "width", size[i]);
			return -1;
		}
		if (r < (i < 2 ? 0 : -1)) {
			diag_error(SRC_NOWHERE, "%s: %g is before the image's first pixel", names[i], v);
			return -1;
		}
		rect[i] = (int)r;
	}
	if (rect[CLI_REGION_RIGHT] < rect[CLI_REGION_LEFT] || rect[CLI_REGION_BOTTOM] < rect[CLI_REGION_TOP]) {
		diag_error(SRC_NOWHERE, "the part of the image to render (+SC +SR +EC +ER) is empty");
		return -1;
	}
	return p->region_given ? 1 : 0;
}
