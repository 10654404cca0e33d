// glfx_compare - compares two scene dumps (Mesa vs libglfixed), prints one
// table row, writes mesa.png / glfixed.png / diff.png (and optionally a
// side-by-side PNG).  File format: see scenes/scene.h.
//
// usage: glfx_compare [options] NAME MESA_PREFIX GLFIXED_PREFIX OUTDIR
//        glfx_compare --header
// options:
//   --side-by-side FILE   also write FILE = mesa | glfixed | diff
//   --scale N             nearest-neighbour upscale of the side-by-side PNG
//   --verbose             per-image details on stderr
// Exit status: 0 PASS, 1 FAIL, 2 usage / unreadable input.

#include <png.h>

#include <algorithm>
#include <cerrno>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace {

struct Image {
    bool present = false;
    std::string error;               // non-empty: could not be read
    int width = 0, height = 0;
    int channels = 4;                // channels that count for coverage
    int depth_w = 0, depth_h = 0, depth_bytes = 0;
    uint32_t cleared_depth = 0;
    int guard_damage = 0;
    std::map<std::string, std::string> info;
    std::vector<uint8_t> rgba;       // width*height*4, top row first (8-bit, for the pictures)
    std::vector<uint8_t> depth;      // depth_w*depth_h*depth_bytes
    // The samples in the buffer's precision (header field 10, scene.c's
    // sample_kind): "8" bytes, "16" 16-bit unorm, "32f" floats as ordered
    // integers (so a difference is in units in the last place), "565" the
    // 5-6-5 channels' own values. Differences count in those units.
    std::string kind = "8";
    std::vector<int64_t> val;        // width*height*4
    int64_t key[4] = {3, 5, 7, 0};   // the KEY clear in that precision

    bool has_depth() const { return depth_bytes > 0 && depth_w == width && depth_h == height; }
    uint32_t depth_at(size_t i) const {
        uint32_t v = 0;
        const uint8_t *p = &depth[i * depth_bytes];
        for (int b = depth_bytes - 1; b >= 0; b--) v = (v << 8) | p[b];   // little endian
        return v;
    }
    bool covered(size_t i) const {
        for (int c = 0; c < channels; c++)
            if (val[i * 4 + c] != key[c]) return true;
        return has_depth() && depth_at(i) != cleared_depth;
    }
};

bool file_exists(const std::string &path) {
    FILE *f = std::fopen(path.c_str(), "rb");
    if (!f) return false;
    std::fclose(f);
    return true;
}

Image load(const std::string &path) {
    Image im;
    FILE *f = std::fopen(path.c_str(), "rb");
    if (!f) return im;
    im.present = true;
    char line[4096];
    char kind[16] = "8";
    unsigned cleared = 0;
    int fields = 0;
    if (!std::fgets(line, sizeof line, f) ||
        (fields = std::sscanf(line, "GLFX1 %d %d %d %d %d %d %u %d %15s", &im.width, &im.height, &im.channels,
                              &im.depth_w, &im.depth_h, &im.depth_bytes, &cleared, &im.guard_damage, kind)) < 8 ||
        (std::strcmp(kind, "8") != 0 && std::strcmp(kind, "16") != 0 && std::strcmp(kind, "32f") != 0 &&
         std::strcmp(kind, "565") != 0) ||
        im.width <= 0 || im.height <= 0 || im.width > 16384 || im.height > 16384 ||
        im.depth_w < 0 || im.depth_h < 0 || im.depth_w > 16384 || im.depth_h > 16384 ||
        im.depth_bytes < 0 || im.depth_bytes > 4) {
        im.error = "bad header";
        std::fclose(f);
        return im;
    }
    im.cleared_depth = cleared;
    if (!std::fgets(line, sizeof line, f) || std::strncmp(line, "info", 4) != 0) {
        im.error = "bad info line";
        std::fclose(f);
        return im;
    }
    std::istringstream ss(line + 4);
    std::string kv;
    while (ss >> kv) {
        size_t eq = kv.find('=');
        if (eq != std::string::npos) im.info[kv.substr(0, eq)] = kv.substr(eq + 1);
    }
    im.kind = kind;
    const size_t samples = size_t(im.width) * im.height * 4;
    const int sample_bytes = im.kind == "16" ? 2 : im.kind == "32f" ? 4 : 1;
    std::vector<uint8_t> raw(samples * sample_bytes);
    im.depth.resize(size_t(im.depth_w) * im.depth_h * im.depth_bytes);
    if (std::fread(raw.data(), 1, raw.size(), f) != raw.size() ||
        std::fread(im.depth.data(), 1, im.depth.size(), f) != im.depth.size())
        im.error = "truncated";
    std::fclose(f);
    // A float as an integer ordered like the floats: neighbours differ by 1.
    auto ordered = [](float v) {
        int32_t b;
        std::memcpy(&b, &v, 4);
        return b >= 0 ? int64_t(b) : -int64_t(b & 0x7fffffff);
    };
    if (im.kind == "16") {
        for (int c = 0; c < 4; c++) im.key[c] = int64_t(im.key[c]) * 257;
    } else if (im.kind == "32f") {
        for (int c = 0; c < 4; c++) im.key[c] = ordered(float(im.key[c]) / 255.0f);
    } else if (im.kind == "565") {
        const int64_t k[4] = {0, 1, 1, 0};
        for (int c = 0; c < 4; c++) im.key[c] = k[c];
    }
    im.val.resize(samples);
    im.rgba.resize(samples);
    for (size_t i = 0; i < samples; i++) {
        if (im.kind == "16") {
            uint16_t v;
            std::memcpy(&v, &raw[i * 2], 2);
            im.val[i] = v;
            im.rgba[i] = uint8_t(v >> 8);
        } else if (im.kind == "32f") {
            float v;
            std::memcpy(&v, &raw[i * 4], 4);
            im.val[i] = ordered(v);
            im.rgba[i] = uint8_t(std::lrint(std::min(std::max(v, 0.0f), 1.0f) * 255.0f));
        } else if (im.kind == "565") {
            const int c = int(i % 4), v = raw[i];
            im.val[i] = v;
            im.rgba[i] = c == 3 ? uint8_t(v) : c == 1 ? uint8_t((v << 2) | (v >> 4)) : uint8_t((v << 3) | (v >> 2));
        } else {
            im.val[i] = raw[i];
            im.rgba[i] = raw[i];
        }
    }
    return im;
}

bool write_png(const std::string &path, int w, int h, const std::vector<uint8_t> &rgb) {
    FILE *f = std::fopen(path.c_str(), "wb");
    if (!f) return false;
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    if (!png || !info || setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        std::fclose(f);
        return false;
    }
    png_init_io(png, f);
    png_set_IHDR(png, info, w, h, 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    for (int y = 0; y < h; y++)
        png_write_row(png, const_cast<png_bytep>(&rgb[size_t(y) * w * 3]));
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    return std::fclose(f) == 0;
}

std::vector<uint8_t> to_rgb(const Image &im) {
    std::vector<uint8_t> out(size_t(im.width) * im.height * 3);
    for (size_t i = 0, n = size_t(im.width) * im.height; i < n; i++)
        for (int c = 0; c < 3; c++) out[i * 3 + c] = im.rgba[i * 4 + c];
    return out;
}

struct Stats {
    long covered = 0;        // covered in the Mesa image
    long coverage_mismatch = 0;
    long exact = 0;          // covered in both, all 4 channels identical
    long off_by_one = 0;     // covered in both, max channel difference 1
    long worse = 0;          // covered in both, max channel difference > 1
    int max_diff = 0;        // over pixels covered in both
    long depth_diff_pixels = 0;
    uint32_t depth_max_diff = 0;
};

// Compares a against b, accumulates into st, fills diff (RGB) when non-null.
void compare(const Image &a, const Image &b, Stats &st, std::vector<uint8_t> *diff) {
    const size_t n = size_t(a.width) * a.height;
    if (diff) diff->assign(n * 3, 0);
    const bool depth_both = a.has_depth() && b.has_depth() && a.depth_bytes == b.depth_bytes;
    for (size_t i = 0; i < n; i++) {
        const bool ca = a.covered(i), cb = b.covered(i);
        uint8_t *d = diff ? &(*diff)[i * 3] : nullptr;
        if (ca) st.covered++;
        if (depth_both) {
            uint32_t da = a.depth_at(i), db = b.depth_at(i);
            uint32_t dd = da > db ? da - db : db - da;
            if (dd) st.depth_diff_pixels++;
            st.depth_max_diff = std::max(st.depth_max_diff, dd);
        }
        if (ca != cb) {
            st.coverage_mismatch++;
            if (d) {  // magenta: only Mesa covers it, cyan: only glfixed
                d[0] = ca ? 255 : 0; d[1] = ca ? 0 : 255; d[2] = 255;
            }
            continue;
        }
        if (!ca) continue;  // both uncovered: identical key colour (black)
        int64_t md64 = 0;
        for (int c = 0; c < 4; c++)
            md64 = std::max<int64_t>(md64, std::llabs(a.val[i * 4 + c] - b.val[i * 4 + c]));
        const int md = int(std::min<int64_t>(md64, 1 << 30));
        st.max_diff = std::max(st.max_diff, md);
        if (md == 0) {
            st.exact++;
        } else if (md == 1) {
            st.off_by_one++;
            if (d) d[0] = d[1] = d[2] = 128;
        } else {
            st.worse++;
            if (d) { d[0] = 255; d[1] = 0; d[2] = 0; }
        }
    }
}

std::vector<uint8_t> side_by_side(int w, int h, const std::vector<std::vector<uint8_t>> &panels,
                                  int scale, int &out_w, int &out_h) {
    const int gap = 4;
    const int sw = w * scale, sh = h * scale;
    out_w = int(panels.size()) * sw + (int(panels.size()) - 1) * gap;
    out_h = sh;
    std::vector<uint8_t> out(size_t(out_w) * out_h * 3, 255);  // white separators
    for (size_t p = 0; p < panels.size(); p++) {
        const int x0 = int(p) * (sw + gap);
        for (int y = 0; y < sh; y++)
            for (int x = 0; x < sw; x++) {
                const uint8_t *s = &panels[p][(size_t(y / scale) * w + x / scale) * 3];
                uint8_t *d = &out[(size_t(y) * out_w + x0 + x) * 3];
                d[0] = s[0]; d[1] = s[1]; d[2] = s[2];
            }
    }
    return out;
}

const char *kHeaderFmt = "%-28s %9s %9s %17s %8s %8s %4s  %-4s  %s\n";

void print_header() {
    std::printf(kHeaderFmt, "scene", "covered", "cov_mism", "exact (%)", "off_by_1", "worse",
                "max", "res", "notes");
}

void print_row(const std::string &name, const Stats &st, bool pass, const std::string &notes) {
    char exact[64];
    double pct = st.covered ? 100.0 * double(st.exact) / double(st.covered) : 100.0;
    // Never show 100.00% unless every covered pixel is exact.
    if (st.exact < st.covered && pct > 99.99) pct = 99.99;
    std::snprintf(exact, sizeof exact, "%ld (%.2f%%)", st.exact, pct);
    char c1[32], c2[32], c3[32], c4[32], c5[32];
    std::snprintf(c1, sizeof c1, "%ld", st.covered);
    std::snprintf(c2, sizeof c2, "%ld", st.coverage_mismatch);
    std::snprintf(c3, sizeof c3, "%ld", st.off_by_one);
    std::snprintf(c4, sizeof c4, "%ld", st.worse);
    std::snprintf(c5, sizeof c5, "%d", st.max_diff);
    std::printf(kHeaderFmt, name.c_str(), c1, c2, exact, c3, c4, c5, pass ? "PASS" : "FAIL",
                notes.c_str());
}

void print_error_row(const std::string &name, const std::string &notes) {
    std::printf(kHeaderFmt, name.c_str(), "-", "-", "-", "-", "-", "-", "FAIL", notes.c_str());
}

int usage() {
    std::fprintf(stderr,
                 "usage: glfx_compare [--side-by-side FILE] [--scale N] [--verbose]\n"
                 "                    NAME MESA_PREFIX GLFIXED_PREFIX OUTDIR\n"
                 "       glfx_compare --header\n"
                 "       glfx_compare --error-row NAME MESSAGE\n");
    return 2;
}

}  // namespace

int main(int argc, char **argv) {
    std::string sbs_path;
    int scale = 1;
    bool verbose = false;
    std::vector<std::string> pos;
    for (int i = 1; i < argc; i++) {
        std::string a = argv[i];
        if (a == "--header") {
            print_header();
            return 0;
        } else if (a == "--error-row" && i + 2 < argc) {
            print_error_row(argv[i + 1], argv[i + 2]);
            return 1;
        } else if (a == "--side-by-side" && i + 1 < argc) {
            sbs_path = argv[++i];
        } else if (a == "--scale" && i + 1 < argc) {
            scale = std::max(1, std::min(64, std::atoi(argv[++i])));
        } else if (a == "--verbose") {
            verbose = true;
        } else if (!a.empty() && a[0] == '-') {
            return usage();
        } else {
            pos.push_back(a);
        }
    }
    if (pos.size() != 4) return usage();
    const std::string &name = pos[0], &mesa_prefix = pos[1], &glfx_prefix = pos[2],
                      &outdir = pos[3];

    Image ma = load(mesa_prefix + ".glfx");
    Image ga = load(glfx_prefix + ".glfx");
    if (!ma.present || !ma.error.empty()) {
        print_error_row(name, ma.present ? "Mesa output " + ma.error : "no Mesa output");
        return 1;
    }
    if (!ga.present || !ga.error.empty()) {
        print_error_row(name, ga.present ? "glfixed output " + ga.error : "no glfixed output");
        return 1;
    }

    std::vector<std::string> notes;
    bool pass = true;
    Stats st;

    if (ma.width != ga.width || ma.height != ga.height || ma.channels != ga.channels || ma.kind != ga.kind) {
        char buf[160];
        std::snprintf(buf, sizeof buf, "size/format differ: %dx%dx%d vs %dx%dx%d", ma.width,
                      ma.height, ma.channels, ga.width, ga.height, ga.channels);
        print_error_row(name, buf);
        return 1;
    }

    // Colour buffer.
    std::vector<uint8_t> diff;
    compare(ma, ga, st, &diff);
    if (ma.has_depth() != ga.has_depth() || ma.depth_bytes != ga.depth_bytes) {
        char buf[96];
        std::snprintf(buf, sizeof buf, "depth buffer differs: %d vs %d bytes/value",
                      ma.has_depth() ? ma.depth_bytes : 0, ga.has_depth() ? ga.depth_bytes : 0);
        notes.push_back(buf);
        pass = false;
    } else if (st.depth_diff_pixels) {
        char buf[96];
        std::snprintf(buf, sizeof buf, "depth: %ld px differ (max %" PRIu32 ")",
                      st.depth_diff_pixels, st.depth_max_diff);
        notes.push_back(buf);   // informational only
    }
    if (ma.guard_damage != ga.guard_damage) {
        notes.push_back("client buffer bytes outside image modified: " +
                        std::to_string(ma.guard_damage) + " vs " +
                        std::to_string(ga.guard_damage));
        pass = false;
    }
    if (ma.info.count("mesa_rgb_via_rgba"))
        notes.push_back("Mesa side: OSMESA_RGB emulated with RGBA (llvmpipe RGB bug)");
    for (const auto &kv : ma.info) {
        if (kv.first == "mesa_rgb_via_rgba") continue;
        auto it = ga.info.find(kv.first);
        std::string other = it == ga.info.end() ? "?" : it->second;
        if (other != kv.second) notes.push_back(kv.first + " " + kv.second + "/" + other);
    }

    // glReadPixels dump, when either side wrote one.
    const std::string mrp = mesa_prefix + ".readpixels", grp = glfx_prefix + ".readpixels";
    const bool have_mrp = file_exists(mrp), have_grp = file_exists(grp);
    Stats rst;
    bool rp_compared = false;
    if (have_mrp || have_grp) {
        Image mr = load(mrp), gr = load(grp);
        if (!mr.present || !gr.present || !mr.error.empty() || !gr.error.empty()) {
            notes.push_back(std::string("readpixels: ") +
                            (!mr.present ? "missing on Mesa"
                             : !gr.present ? "missing on glfixed"
                             : !mr.error.empty() ? "Mesa " + mr.error
                                                 : "glfixed " + gr.error));
            pass = false;
        } else if (mr.width != gr.width || mr.height != gr.height) {
            notes.push_back("readpixels: size differs");
            pass = false;
        } else {
            std::vector<uint8_t> rdiff;
            compare(mr, gr, rst, &rdiff);
            rp_compared = true;
            if (rst.coverage_mismatch || rst.off_by_one || rst.worse) {
                char buf[128];
                std::snprintf(buf, sizeof buf, "readpixels: %ld cov_mism, %ld off_by_1, %ld worse",
                              rst.coverage_mismatch, rst.off_by_one, rst.worse);
                notes.push_back(buf);
                write_png(outdir + "/diff_readpixels.png", mr.width, mr.height, rdiff);
            } else {
                notes.push_back("readpixels ok");
            }
        }
    }

    // The row shows the sum over the compared images (colour buffer + readpixels).
    Stats total = st;
    if (rp_compared) {
        total.covered += rst.covered;
        total.coverage_mismatch += rst.coverage_mismatch;
        total.exact += rst.exact;
        total.off_by_one += rst.off_by_one;
        total.worse += rst.worse;
        total.max_diff = std::max(total.max_diff, rst.max_diff);
    }
    auto ok = [](const Stats &s) {
        // exact >= 99.99% of covered, in integers: exact * 10000 >= covered * 9999
        return s.coverage_mismatch == 0 && s.max_diff <= 1 &&
               s.exact * 10000 >= s.covered * 9999;
    };
    if (!ok(st) || (rp_compared && !ok(rst))) pass = false;
    if (ma.info.count("gl_error") && ma.info["gl_error"] != "0x0000")
        notes.push_back("Mesa raised a GL error");
    const bool m_refused = ma.info.count("refused") != 0;
    const bool g_refused = ga.info.count("refused") != 0;
    if (m_refused && g_refused)
        notes.push_back("both refused the context (" + ma.info["refused"] + ")");
    else if (m_refused || g_refused)
        notes.push_back(std::string(m_refused ? "only Mesa" : "only glfixed") +
                        " refused the context");
    else if (st.covered == 0)
        notes.push_back("WARNING: nothing covered");

    // Pictures.
    std::vector<uint8_t> mrgb = to_rgb(ma), grgb = to_rgb(ga);
    bool png_ok = write_png(outdir + "/mesa.png", ma.width, ma.height, mrgb) &&
                  write_png(outdir + "/glfixed.png", ga.width, ga.height, grgb) &&
                  write_png(outdir + "/diff.png", ma.width, ma.height, diff);
    if (!sbs_path.empty()) {
        int w = 0, h = 0;
        std::vector<uint8_t> sbs = side_by_side(ma.width, ma.height, {mrgb, grgb, diff}, scale, w, h);
        png_ok = write_png(sbs_path, w, h, sbs) && png_ok;
    }
    if (!png_ok) notes.push_back("could not write PNGs");

    std::string joined;
    for (size_t i = 0; i < notes.size(); i++) joined += (i ? "; " : "") + notes[i];
    print_row(name, total, pass, joined);

    if (verbose) {
        std::fprintf(stderr,
                     "%s: colour buffer covered=%ld cov_mism=%ld exact=%ld off1=%ld worse=%ld max=%d\n",
                     name.c_str(), st.covered, st.coverage_mismatch, st.exact, st.off_by_one,
                     st.worse, st.max_diff);
        if (rp_compared)
            std::fprintf(stderr,
                         "%s: readpixels    covered=%ld cov_mism=%ld exact=%ld off1=%ld worse=%ld max=%d\n",
                         name.c_str(), rst.covered, rst.coverage_mismatch, rst.exact,
                         rst.off_by_one, rst.worse, rst.max_diff);
        std::fprintf(stderr, "%s: depth %d bytes, %ld px differ, max diff %" PRIu32 "\n",
                     name.c_str(), ma.depth_bytes, st.depth_diff_pixels, st.depth_max_diff);
    }
    return pass ? 0 : 1;
}
