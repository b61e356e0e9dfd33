// image_oiio.cpp: the only file that talks to OpenImageIO.
#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>
#include <OpenImageIO/strutil.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <cerrno>
#include <cstdio>
#include <string>
#include <fcntl.h>
#include <unistd.h>
#include <vector>

#include "image.h"

using namespace OIIO;

/* Files are read in forked children (src/loader.c). A thread pool that
 * OpenEXR made in the parent (OpenImageIO makes it as soon as it looks at an
 * .exr name) is in a child without its threads, and a read there waits for
 * them forever: OpenEXR works in the calling thread, set before it makes a
 * pool. */
static const bool exr_without_threads = OIIO::attribute("exr_threads", -1);

static bool is_linear_format(const std::string &path)
{
	std::string ext = Strutil::lower(Filesystem::extension(path));
	return ext == ".exr" || ext == ".hdr" || ext == ".tif" || ext == ".tiff" || ext == ".pfm";
}

static float srgb_encode(float c)
{
	c = c < 0.0f ? 0.0f : c > 1.0f ? 1.0f : c;
	return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

static int fail(char *err, size_t errlen, const std::string &msg)
{
	std::snprintf(err, errlen, "%s", msg.c_str());
	return -1;
}

extern "C" int image_format_known(const char *path)
{
	auto out = ImageOutput::create(path);
	return out ? 1 : 0;
}

/* "" when the file just written is on the disk and reads back whole; else why
 * not. Some of OpenImageIO's writers (PNG's) do not look at what fwrite says,
 * so a full disk would make an empty or cut image that claims success: the
 * file is synced (a full disk's delayed blocks fail here) and decoded. */
static std::string written_whole(const std::string &tmp, int width, int height)
{
	int fd = open(tmp.c_str(), O_RDONLY);
	if (fd < 0 || fsync(fd) != 0) {
		std::string why = std::strerror(errno);
		if (fd >= 0)
			close(fd);
		return why;
	}
	close(fd);
	auto in = ImageInput::open(tmp);
	if (!in)
		return "the file written does not read back (" + OIIO::geterror() + "): is the disk full?";
	const ImageSpec &spec = in->spec();
	/* decoded as stored: a conversion to float would only cost time */
	bool ok = spec.width == width && spec.height == height;
	std::vector<unsigned char> px(ok ? spec.image_bytes(true) : 0);
	ok = ok && in->read_image(0, 0, 0, spec.nchannels, TypeDesc::UNKNOWN, px.data());
	std::string why = ok ? "" : "the file written does not read back whole (" + in->geterror() + "): is the disk full?";
	in->close();
	return why;
}

extern "C" void image_temp_path(const char *path, char *out, size_t n)
{
	std::string p(path), dir = Filesystem::parent_path(p);
	snprintf(out, n, "%s.%s.eclat-%ld.tmp", dir.empty() ? "" : (dir + "/").c_str(), Filesystem::filename(p).c_str(),
	         (long)getpid());
}

extern "C" int image_finish(const char *tmp, const char *path, const char *write_error, int width, int height,
                            char *err, size_t errlen)
{
	std::string p(path), why = write_error ? write_error : written_whole(tmp, width, height);
	if (write_error || !why.empty()) {
		Filesystem::remove(tmp);
		return fail(err, errlen, "cannot write '" + p + "': " + why);
	}
	if (std::rename(tmp, path) != 0) {
		why = std::strerror(errno);
		Filesystem::remove(tmp);
		return fail(err, errlen, "cannot write '" + p + "': " + why);
	}
	return 0;
}

extern "C" int image_format_alpha(const char *path)
{
	auto out = ImageOutput::create(path);
	return out && out->supports("alpha") ? 1 : 0;
}

/* RGB and alpha as the file wants them: linear formats keep the colours
 * associated with alpha (OpenEXR's rule); the others get them divided by it,
 * as PNG stores them, before their transfer. */
static std::vector<float> with_alpha(const float *rgb, const float *alpha, size_t n, bool linear)
{
	std::vector<float> px(n * 4);
	for (size_t i = 0; i < n; i++) {
		float a = alpha[i] < 0.0f ? 0.0f : alpha[i] > 1.0f ? 1.0f : alpha[i];
		float k = linear || a <= 0.0f ? 1.0f : 1.0f / a;
		for (int c = 0; c < 3; c++)
			px[4 * i + c] = rgb[3 * i + c] * k;
		px[4 * i + 3] = a;
	}
	return px;
}

/* The pixels, opened, into the file. write_image would convert floats to the
 * file's 8 or 16 bits a scanline at a time on OpenImageIO's threads, which
 * wake for every scanline: this saves about 30 ms of the 120 ms PNG write of
 * make bench's Whitted race (issue 18), and its own conversion run here once
 * gives the same bytes. */
static bool write_pixels(ImageOutput *out, const std::vector<float> &pixels)
{
	TypeDesc stored = out->spec().format;
	if (stored != TypeDesc::UINT8 && stored != TypeDesc::UINT16)
		return out->write_image(TypeDesc::FLOAT, pixels.data());
	std::vector<unsigned char> fixed(pixels.size() * stored.size());
	const size_t chunk = (size_t)1 << 24;   /* convert_pixel_values counts in int */
	for (size_t i = 0; i < pixels.size(); i += chunk)
		if (!convert_pixel_values(TypeDesc::FLOAT, &pixels[i], stored, &fixed[i * stored.size()],
		                          (int)std::min(chunk, pixels.size() - i)))
			return out->write_image(TypeDesc::FLOAT, pixels.data());
	return out->write_image(stored, fixed.data());
}

/* Writes pixels (channels floats a pixel) to a temporary file beside path, then
 * renames it: the file appears whole or not at all. srgb: encode the values for
 * an 8-bit format; they are display values already when not. */
static int write_atomic(const std::string &p, const float *rgb, int width, int height, int channels,
                        bool srgb, const image_meta *meta, char *err, size_t errlen)
{
	auto out = ImageOutput::create(p);
	if (!out)
		return fail(err, errlen, "cannot write '" + p + "': no image format for this extension");
	bool linear = is_linear_format(p);
	bool alpha = meta && meta->alpha && channels == 3;
	TypeDesc fixed = meta && meta->bits > 8 ? TypeDesc::UINT16 : TypeDesc::UINT8;   // formats without 16 bits get 8
	ImageSpec spec(width, height, alpha ? 4 : channels, linear ? TypeDesc::FLOAT : fixed);
	if (alpha) {
		spec.alpha_channel = 3;
		if (!linear)   // with_alpha divided them, before the transfer as it must be
			spec.attribute("oiio:UnassociatedAlpha", 1);
	}
	spec.attribute("oiio:ColorSpace", linear ? "Linear" : "sRGB");
	if (!linear && fixed == TypeDesc::UINT16)   // PNM's writer reads the depth from here
		spec.attribute("oiio:BitsPerSample", 16);
	spec.attribute("Software", "eclat " PACKAGE_VERSION);
	if (meta && meta->scene)
		spec.attribute("eclat:scene", meta->scene);
	if (meta)
		spec.attribute("eclat:samples", (int)meta->samples);

	size_t n = (size_t)width * height;
	std::vector<float> pixels = alpha ? with_alpha(rgb, meta->alpha, n, linear)
	                                  : std::vector<float>(rgb, rgb + n * channels);
	if (!linear && srgb)
		for (size_t i = 0; i < pixels.size(); i++)
			if (!alpha || i % 4 != 3)
				pixels[i] = srgb_encode(pixels[i]);

	char tmp[4200];
	image_temp_path(p.c_str(), tmp, sizeof tmp);
	if (!out->open(tmp, spec))   /* opening may have made tmp before failing to write its header */
		return image_finish(tmp, p.c_str(), out->geterror().c_str(), width, height, err, errlen);
	bool ok = write_pixels(out.get(), pixels);
	std::string msg = out->geterror();
	ok = out->close() && ok;
	if (!ok && msg.empty())
		msg = out->geterror();
	return image_finish(tmp, p.c_str(), ok ? NULL : msg.c_str(), width, height, err, errlen);
}

extern "C" int image_write(const char *path, const float *rgb, int width, int height,
                           const image_meta *meta, char *err, size_t errlen)
{
	return write_atomic(path, rgb, width, height, 3, true, meta, err, errlen);
}

extern "C" void image_encode8(const float *linear, size_t n, unsigned char *out)
{
	for (size_t i = 0; i < n; i++)   // write_image's own conversion of the encoded floats
		out[i] = convert_type<float, unsigned char>(srgb_encode(linear[i]));
}

extern "C" int image_read_here(const char *path, long max_texels, image_data *out, char *err, size_t errlen)
{
	std::string p(path);
	*out = image_data();
	auto in = ImageInput::open(p);
	if (!in) {
		std::string why = OIIO::geterror();
		return fail(err, errlen, why.empty() ? "no image format reads it" : why);
	}
	const ImageSpec spec = in->spec();   /* a copy: reading may change the reader's own (GIF's does) */
	/* The header is all that was read: what it claims is checked before the
	 * decoder allocates for it (a tiny file may claim 100000 x 100000). */
	long texels = (long)spec.width * spec.height;
	char msg[200];
	if (spec.width <= 0 || spec.height <= 0 || spec.depth > 1) {
		std::snprintf(msg, sizeof msg, "its header claims %d x %d x %d pixels: a corrupt file?", spec.width,
		              spec.height, spec.depth);
		return fail(err, errlen, msg);
	}
	if (spec.width > IMAGE_MAX_SIDE || spec.height > IMAGE_MAX_SIDE || texels > max_texels) {
		std::snprintf(msg, sizeof msg, "its header says %d x %d pixels, more than the %ld pixels (%d on a side) an image may have",
		              spec.width, spec.height, max_texels, IMAGE_MAX_SIDE);
		return fail(err, errlen, msg);
	}
	if (spec.nchannels < 1 || spec.nchannels > 16 || spec.deep) {
		std::snprintf(msg, sizeof msg, "it has %d channels%s: not an image eclat reads", spec.nchannels,
		              spec.deep ? ", deep" : "");
		return fail(err, errlen, msg);
	}
	int nc = spec.nchannels;
	std::vector<float> px((size_t)texels * nc);
	if (!in->read_image(0, 0, 0, nc, TypeDesc::FLOAT, px.data())) {
		std::string why = in->geterror();
		return fail(err, errlen, why.empty() ? "it could not be decoded" : why);
	}
	float *rgba = (float *)std::malloc((size_t)texels * 4 * sizeof(float));
	if (!rgba)
		return fail(err, errlen, "out of memory");
	int alpha = spec.alpha_channel >= 0 && spec.alpha_channel < nc ? spec.alpha_channel : nc == 2 || nc == 4 ? nc - 1 : -1;
	for (long i = 0; i < texels; i++) {
		const float *s = &px[(size_t)i * nc];
		float *d = &rgba[(size_t)i * 4];
		bool grey = nc < 3;
		d[0] = s[0];
		d[1] = grey ? s[0] : s[1];
		d[2] = grey ? s[0] : s[2];
		d[3] = alpha >= 0 ? s[alpha] : 1.0f;
	}
	out->rgba = rgba;
	out->width = spec.width;
	out->height = spec.height;
	std::string cs = Strutil::lower(spec.get_string_attribute("oiio:ColorSpace"));
	float g = spec.get_float_attribute("oiio:Gamma", 0.0f);
	bool is_float = spec.format.basetype == TypeDesc::FLOAT || spec.format.basetype == TypeDesc::HALF;
	out->encoding = cs == "srgb" ? IMAGE_GAMMA_SRGB : g > 0 && Strutil::starts_with(cs, "gamma") ? IMAGE_GAMMA_POWER
	              : cs == "linear" || is_float ? IMAGE_GAMMA_LINEAR : IMAGE_GAMMA_UNKNOWN;
	out->gamma = g;
	out->premultiplied = alpha >= 0 && !spec.get_int_attribute("oiio:UnassociatedAlpha", 0) &&
	                     std::strcmp(in->format_name(), "openexr") == 0;
	std::snprintf(out->format, sizeof out->format, "%s", in->format_name());
	out->channels = nc;
	int bits = spec.get_int_attribute("oiio:BitsPerSample", 0);
	out->bits = bits > 0 ? bits : (int)spec.format.size() * 8;
	in->close();
	return 0;
}

/* A round number at or above v, for the legend's scale: 1, 2, 5 times a power of ten. */
static float nice_ceiling(float v)
{
	if (!(v > 0))
		return 1;
	float p = std::pow(10.0f, std::floor(std::log10(v)));
	for (float m : { 1.0f, 2.0f, 5.0f, 10.0f })
		if (m * p >= v)
			return m * p;
	return 10 * p;
}

static const char *const legend_font = "DejaVuSans";

extern "C" int image_write_heat(const char *path, const float *heat, int width, int height,
                                const image_meta *meta, double *mean, char *err, size_t errlen)
{
	size_t n = (size_t)width * height;
	double sum = 0;
	float top = 0;
	for (size_t i = 0; i < n; i++) {
		sum += heat[i];
		top = std::max(top, heat[i]);
	}
	*mean = n ? sum / n : 0;
	std::string p(path);
	if (is_linear_format(p)) {   /* the counts themselves, in every channel */
		std::vector<float> rgb(n * 3);
		for (size_t i = 0; i < n; i++)
			rgb[3 * i] = rgb[3 * i + 1] = rgb[3 * i + 2] = heat[i];
		return write_atomic(p, rgb.data(), width, height, 3, false, meta, err, errlen);
	}
	/* The paper's figure: a colour map, and under it a legend with its scale and units. */
	float scale = nice_ceiling(top);
	ImageBuf counts(ImageSpec(width, height, 1, TypeDesc::FLOAT), (void *)heat);
	ImageBuf mapped = ImageBufAlgo::color_map(ImageBufAlgo::mul(counts, 1.0f / scale), 0, "turbo");
	int w = std::max(width, 360), legend = 64, ramp_w = w - 40;
	ImageBuf canvas(ImageSpec(w, height + legend, 3, TypeDesc::FLOAT));
	ImageBufAlgo::zero(canvas);
	ImageBufAlgo::paste(canvas, (w - width) / 2, 0, 0, 0, mapped);
	ImageBuf ramp(ImageSpec(ramp_w, 12, 1, TypeDesc::FLOAT));
	for (ImageBuf::Iterator<float> it(ramp); !it.done(); ++it)
		it[0] = (float)it.x() / (ramp_w - 1);
	ImageBufAlgo::paste(canvas, 20, height + 10, 0, 0, ImageBufAlgo::color_map(ramp, 0, "turbo"));
	char text[160];
	const float white[3] = { 1, 1, 1 };
	bool ok = ImageBufAlgo::render_text(canvas, 20, height + 38, "0", 14, legend_font, white);
	snprintf(text, sizeof text, "%g", scale);
	ok = ok && ImageBufAlgo::render_text(canvas, 20 + ramp_w, height + 38, text, 14, legend_font, white,
	                                     ImageBufAlgo::TextAlignX::Right);
	snprintf(text, sizeof text, "BVH tests per camera ray (mean %.1f)", *mean);
	ok = ok && ImageBufAlgo::render_text(canvas, w / 2, height + 56, text, 14, legend_font, white,
	                                     ImageBufAlgo::TextAlignX::Center);
	if (!ok)
		return fail(err, errlen, "cannot draw the heat map's legend: " + canvas.geterror() +
		                         " (the font DejaVu Sans comes with fonts-dejavu-core)");
	std::vector<float> pixels((size_t)w * (height + legend) * 3);
	canvas.get_pixels(ROI::All(), TypeDesc::FLOAT, pixels.data());
	return write_atomic(p, pixels.data(), w, height + legend, 3, false, meta, err, errlen);
}
