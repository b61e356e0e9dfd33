/* cli_pov.h: POV-Ray's command line and INI files, read as eclat's options.
 *
 *   eclat +W320 +H240 -D +A0.3 +FN16 render.ini[Low] +Iscene.pov -s 16
 *
 * cli_pov_args rewrites the arguments into eclat's own long options, in their
 * order ("+W320" becomes "--width=320"), so that of two settings the later wins
 * whichever way each is spelled, as in POV-Ray; an INI file named among them
 * (cli_ini.c) is read at its place. What eclat has no option for (the scene
 * named by +I, the output type, the animation's clock) is kept in a cli_pov. */
#ifndef ECLAT_CLI_POV_H
#define ECLAT_CLI_POV_H

#include <getopt.h>

#include "diag.h"

typedef struct {
	const char *scene;           /* the last scene named, plainly, by +I or Input_File_Name */
	int n_plain_scenes;          /* named plainly on the command line: more than one is an error */
	const char *after_display;   /* the argument after a bare -D, for a hint when it was meant as -D NAME */
	char file_type;              /* +F's letter in upper case ('N': PNG...); 0: not given */
	int bits;                    /* +FN16: 16; 0: the format's own */
	int alpha;                   /* +UA, Output_Alpha: the image gets an alpha channel */
	int antialias;               /* +A: 1, -A: 0, not given: -1 */
	/* the whitted integrator's anti-aliasing as POV-Ray's switches set it (POV-Ray's
	 * defaults: +AM1 +A0.3 +R3 +AG2.5 +J1.0) */
	int aa_method, aa_depth, jitter;
	double aa_threshold, aa_gamma, jitter_amount;
	int anim;                    /* Initial_Frame or Final_Frame was given */
	int clock_given, cyclic, subset_start_given, subset_end_given;
	double clock, initial_clock, final_clock;
	long initial_frame, final_frame;
	long frame_step;             /* +STP, Frame_Step: every Nth frame (0 as 1) */
	double subset_start, subset_end;   /* a frame, or -1 - a fraction of the animation */
	double region[4];            /* +SC +SR +EC +ER as given, ORDER CLI_REGION_ */
	int region_given;            /* a bit for each */
} cli_pov;

/* The animation's values at one frame, by POV-Ray 3.7's formulas (its
 * animationprocessing.cpp); digits: the width of the frame number in the
 * output's name (that of final_frame), 0 without a frame range. The frames
 * asked for are first .. first + frames - 1 (+SF, +EF). */
typedef struct {
	double clock, clock_delta, initial_clock, final_clock;
	int clock_on, digits;
	long frame, initial_frame, final_frame;
	long first, frames, step;   /* frame k of the frames rendered is first + k * step */
} cli_frame;

/* Rewrites argv (kept: argv[0]) into eclat's options in *out, NULL-terminated,
 * and returns their count. longopts and shortopts are getopt_long's, so that an
 * option's separate argument ("-o +x.png") is passed on untouched. Exits 1 with
 * a message for a switch POV-Ray does not know or a bad INI file; warns about
 * what eclat accepts but cannot honour. */
int cli_pov_args(int argc, char **argv, const struct option *longopts, const char *shortopts,
                 cli_pov *pov, char ***out);

/* The animation asked for, at its first frame. */
void cli_pov_frame(const cli_pov *pov, cli_frame *f);
/* f at another frame: frame_number and clock. */
void cli_frame_goto(cli_frame *f, long frame);

/* The part of the image POV-Ray's +SC +SR +EC +ER (Start_Column...) ask for,
 * in pixels from 0, inclusive, in rect (ORDER CLI_REGION_). Returns 1 when a
 * part was asked for, 0 when not (the whole image), -1 after an error (a part
 * past the image, or an empty one). */
enum { CLI_REGION_LEFT, CLI_REGION_TOP, CLI_REGION_RIGHT, CLI_REGION_BOTTOM };
int cli_pov_region(const cli_pov *pov, int width, int height, int rect[4]);

/* The image's name: output, or the scene's stem in the current folder as POV-Ray
 * names it; f's frame number (with a frame range) goes before the extension,
 * and a name without an extension gets that of +F's type (.png by default).
 * Returns a new string, NULL when out of memory. */
char *cli_pov_output(const cli_pov *pov, const cli_frame *f, const char *scene, const char *output);

/* ---- between cli_pov.c and cli_ini.c */
typedef struct cli_args cli_args;

/* One POV-Ray switch ("+W320"), a KEY=VALUE setting, or a plain argument (a
 * scene, or an INI file "render.ini[Section]"), from the command line
 * (loc SRC_NOWHERE) or an INI file. */
void cli_pov_switch(cli_args *a, const char *sw, src_loc loc);
void cli_pov_setting(cli_args *a, const char *key, const char *value, src_loc key_loc, src_loc value_loc);
void cli_pov_plain(cli_args *a, const char *arg, src_loc loc);
/* Keeps s until exit (NULL: out of memory, exit 1) and returns it. */
char *cli_pov_keep(char *s);
/* Frees what cli_pov_args kept, even after it ended with exit(1): for a caller
 * that reads many command lines in one process (fuzz/fuzz_cli.c). Every string
 * it returned is gone after. */
void cli_pov_release(void);

/* Reads the INI file spec ("file.ini" or "file.ini[Section]"), named at loc,
 * into a. INI files that name each other nest 16 deep at most. Exits 1 on an
 * error. */
void cli_ini_read(cli_args *a, const char *spec, src_loc loc);
/* 1 when arg names an INI file: it ends in ".ini", or has "[Section]" after it. */
int cli_ini_named(const char *arg);

#endif
