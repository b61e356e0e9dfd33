/* preview.h: the preview window (+D, --preview), through SDL2: the film shown
 * as the written image shows it, redrawn between passes.
 *
 *   preview *w = preview_open(width, height, scene);   NULL: no window, said why
 *   between passes, every PREVIEW_EVERY seconds: preview_show(w, film.rgb)
 *   preview_stopped(w): Escape, q or the window closed: stop as Ctrl-C does
 *   preview_pause(w, &stop) after the image is written (+P), preview_close(w)
 *
 * Every SDL call is made from the thread that opened the window. */
#ifndef ECLAT_PREVIEW_H
#define ECLAT_PREVIEW_H

#include <signal.h>

/* Seconds between two pictures: a few a second are enough to watch a render,
 * and each costs a read of the device's film. */
#define PREVIEW_EVERY 0.25

typedef struct preview preview;

/* Opens a window for a width x height image titled after scene, scaled down
 * to fit the screen. Without a display (no DISPLAY or WAYLAND_DISPLAY, or
 * one SDL cannot open) it says so in one line on stderr and returns NULL:
 * the render goes on without a window. */
preview *preview_open(int width, int height, const char *scene);

/* Shows linear rgb (3 floats a pixel, top row first, as image_write takes
 * it) with the sRGB transfer and the clamp of 8-bit images, and reads the
 * window's events. Returns preview_stopped's answer. */
int preview_show(preview *w, const float *rgb);

/* 1 once the user asked the window to stop the render (Escape or q pressed,
 * the window closed). Reads the events waiting. */
int preview_stopped(preview *w);

/* POV-Ray's +P (Pause_When_Done): keeps the window up until p, q, Enter or
 * Escape is pressed, the window is clicked or closed, or *stop is set (a
 * signal). */
void preview_pause(preview *w, volatile sig_atomic_t *stop);

void preview_close(preview *w);

#endif
