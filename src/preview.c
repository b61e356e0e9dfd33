/* preview.c: the preview window, POV-Ray's +D, with SDL2's window surface (no
 * renderer: a picture a few times a second needs no GPU, and the window
 * surface works on any X11 or Wayland display, Xvfb included). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <SDL.h>

#include "diag.h"
#include "image.h"
#include "preview.h"

struct preview {
	SDL_Window *window;
	SDL_Surface *image;    /* the picture at the image's size, RGB24 */
	unsigned char *bytes;  /* its pixels */
	int width, height;
	int stopped;
	char title[256];
};

static void say_no_window(const char *why)
{
	diag_warning(SRC_NOWHERE, "no preview window (+D): %s; rendering without it", why);
}

/* The largest size of at most the image's that the screen's usable area
 * holds, keeping its shape (POV-Ray's SDL display scales down too). */
static void fit_screen(int width, int height, int *w, int *h)
{
	SDL_Rect r;
	double s = 1.0;
	if (SDL_GetDisplayUsableBounds(0, &r) == 0 && r.w > 0 && r.h > 0) {
		if (width > r.w)
			s = (double)r.w / width;
		if (height * s > r.h)
			s = (double)r.h / height;
	}
	*w = width * s < 1 ? 1 : (int)(width * s);
	*h = height * s < 1 ? 1 : (int)(height * s);
}

preview *preview_open(int width, int height, const char *scene)
{
	const char *x11 = getenv("DISPLAY"), *wayland = getenv("WAYLAND_DISPLAY");
	if ((!x11 || !*x11) && (!wayland || !*wayland)) {
		say_no_window("DISPLAY and WAYLAND_DISPLAY are not set");
		return NULL;
	}
	/* eclat's own SIGINT and SIGTERM handlers stop a render cleanly;
	 * SDL's would turn them into a quit event */
	SDL_SetHint(SDL_HINT_NO_SIGNAL_HANDLERS, "1");
	SDL_SetHint(SDL_HINT_VIDEO_ALLOW_SCREENSAVER, "1");
	preview *w = calloc(1, sizeof *w);
	if (!w || SDL_Init(SDL_INIT_VIDEO) != 0) {
		say_no_window(w ? SDL_GetError() : "out of memory");
		free(w);
		return NULL;
	}
	const char *base = strrchr(scene, '/');
	snprintf(w->title, sizeof w->title, "eclat: %s", base ? base + 1 : scene);
	int ww, wh;
	fit_screen(width, height, &ww, &wh);
	w->width = width;
	w->height = height;
	w->window = SDL_CreateWindow(w->title, SDL_WINDOWPOS_UNDEFINED, SDL_WINDOWPOS_UNDEFINED, ww, wh, 0);
	w->bytes = calloc((size_t)width * height, 3);
	w->image = w->bytes ? SDL_CreateRGBSurfaceWithFormatFrom(w->bytes, width, height, 24, width * 3,
	                                                         SDL_PIXELFORMAT_RGB24) : NULL;
	if (!w->window || !w->image) {
		say_no_window(w->bytes ? SDL_GetError() : "out of memory");
		preview_close(w);
		return NULL;
	}
	preview_show(w, NULL);
	return w;
}

/* The picture onto the window, scaled when the window is smaller. */
static void draw(preview *w)
{
	SDL_Surface *screen = SDL_GetWindowSurface(w->window);
	if (!screen)
		return;
	if (screen->w == w->width && screen->h == w->height)
		SDL_BlitSurface(w->image, NULL, screen, NULL);
	else
		SDL_BlitScaled(w->image, NULL, screen, NULL);
	SDL_UpdateWindowSurface(w->window);
}

/* Reads the events waiting; 1 when one of them asks for a stop. */
static int events(preview *w)
{
	SDL_Event e;
	while (SDL_PollEvent(&e)) {
		if (e.type == SDL_QUIT)
			w->stopped = 1;
		else if (e.type == SDL_KEYDOWN && (e.key.keysym.sym == SDLK_ESCAPE || e.key.keysym.sym == SDLK_q))
			w->stopped = 1;
		else if (e.type == SDL_WINDOWEVENT && e.window.event == SDL_WINDOWEVENT_EXPOSED)
			draw(w);
	}
	return w->stopped;
}

int preview_show(preview *w, const float *rgb)
{
	if (rgb)
		image_encode8(rgb, (size_t)w->width * w->height * 3, w->bytes);
	draw(w);
	return events(w);
}

int preview_stopped(preview *w)
{
	return w && events(w);
}

/* What ends POV-Ray's pause (its PauseWhenDoneResumeIsRequested), and Escape. */
static int ends_pause(const SDL_Event *e)
{
	SDL_Keycode k = e->type == SDL_KEYDOWN ? e->key.keysym.sym : 0;
	return e->type == SDL_QUIT || e->type == SDL_MOUSEBUTTONDOWN || k == SDLK_p || k == SDLK_q ||
	       k == SDLK_RETURN || k == SDLK_KP_ENTER || k == SDLK_ESCAPE;
}

void preview_pause(preview *w, volatile sig_atomic_t *stop)
{
	char title[300];
	snprintf(title, sizeof title, "%s [done: press a key]", w->title);
	SDL_SetWindowTitle(w->window, title);
	fprintf(stderr, "eclat: press p, q, Enter or Escape, or click the preview window, to go on\n");
	SDL_Event e = { 0 };
	for (;;) {
		if (stop && *stop)
			break;
		if (!SDL_WaitEventTimeout(&e, 100))
			continue;
		if (ends_pause(&e))
			break;
		if (e.type == SDL_WINDOWEVENT && e.window.event == SDL_WINDOWEVENT_EXPOSED)
			draw(w);
	}
	w->stopped = e.type == SDL_QUIT;   /* a closed window stays closed for the frames after */
	SDL_SetWindowTitle(w->window, w->title);
}

void preview_close(preview *w)
{
	if (!w)
		return;
	if (w->image)
		SDL_FreeSurface(w->image);
	if (w->window)
		SDL_DestroyWindow(w->window);
	free(w->bytes);
	free(w);
	/* No SDL_Quit: it would unload the X11 libraries SDL opened, leaving what
	 * they keep without a name that LeakSanitizer's suppressions could match
	 * (the sanitizer build); the window is gone and the process about to end. */
}
