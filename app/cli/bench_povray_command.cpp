// `lenslab bench povray`: POV-Ray 3.7 and lenslab render the report scene in one run,
// alternately, each as a child process timed whole; the table, both images and crops of the
// two caustics side by side are written to one folder.

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "child_process.h"
#include "commands.h"
#include "image/bitmap_font.h"
#include "image/colour_speckle.h"
#include "image/image_io.h"
#include "render/integrator_names.h"
#include "scene/limits.h"
#include "scene/render_settings.h"
#include "util/atomic_file.h"
#include "util/error.h"

namespace lenslab::cli {

namespace {

namespace fs = std::filesystem;

struct PovrayBenchArgs {
    std::string povray;  // empty: `povray` on PATH
    std::string pov = "bench/report_scene.pov";
    std::string scene = "scenes/report_scene.json";
    std::string out_dir = "bench-povray";
    int64_t photons = 1100000;
    double radius = 0.025;
    int gather_max = 100;
    int repeats = 5;
    int threads = 2;
    int width = 900, height = 900;
    std::string tone_map = "clip";  // lenslab's; POV-Ray's PNG clips
};

// A failure the user can act on: one line, exit 1.
class BenchError : public Error {
public:
    using Error::Error;
};

// What one renderer's runs produced.
struct Side {
    std::vector<double> seconds;
    std::optional<int64_t> caustic_stored, shot, direct_stored;
    // Colour-speckle index (image/colour_speckle.h) inside the glass sphere and in its caustic.
    double speckle_glass = 0, speckle_caustic = 0;
    std::string version;
    std::string last_output;
    std::vector<std::string> command;
};

std::optional<int64_t> match_count(const std::string& text, const std::regex& re, int group = 1) {
    std::smatch m;
    if (!std::regex_search(text, m, re)) return std::nullopt;
    return std::stoll(m[group].str());
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// 1201671 -> "1 201 671", the report's way of writing counts.
std::string grouped(int64_t n) {
    std::string digits = std::to_string(n), out;
    for (size_t i = 0; i < digits.size(); ++i) {
        if (i > 0 && (digits.size() - i) % 3 == 0) out += ' ';
        out += digits[i];
    }
    return out;
}

// Shortest exact-enough form for command lines and labels: 0.025, not 0.025000.
std::string number(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.10g", v);
    return buf;
}

std::string fixed(double v, int decimals) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    return buf;
}

std::string first_line_matching(const std::string& path, const std::string& key) {
    std::ifstream in(path);
    std::string line;
    while (std::getline(in, line)) {
        if (line.rfind(key, 0) != 0) continue;
        const size_t colon = line.find(':');
        if (colon == std::string::npos) continue;
        const size_t start = line.find_first_not_of(" \t", colon + 1);
        return start == std::string::npos ? "" : line.substr(start);
    }
    return "";
}

std::string load_average() {
    std::ifstream in("/proc/loadavg");
    std::string one, five, fifteen;
    in >> one >> five >> fifteen;
    return one.empty() ? "unknown" : one + " " + five + " " + fifteen;
}

// The last few lines of a child's output, for saying why it failed.
std::string tail_lines(const std::string& text, int lines) {
    size_t pos = text.size();
    while (pos > 0 && (text[pos - 1] == '\n' || text[pos - 1] == '\r')) --pos;
    size_t start = pos;
    for (int n = 0; n < lines && start > 0; ++n) {
        start = text.find_last_of('\n', start - 1);
        if (start == std::string::npos) {
            start = 0;
            break;
        }
    }
    std::string t = text.substr(start, pos - start);
    std::replace(t.begin(), t.end(), '\r', '\n');
    while (!t.empty() && t.front() == '\n') t.erase(t.begin());
    return t;
}

void check_ran(const ChildResult& r, const std::string& who) {
    if (r.exited && r.exit_code == 0) return;
    const std::string how =
        r.exited ? "exit code " + std::to_string(r.exit_code) : "killed by a signal";
    throw BenchError(who + " failed (" + how + "); its last output:\n" + tail_lines(r.output, 6));
}

Image8 mirrored(const Image8& img) {
    Image8 out = img;
    for (int y = 0; y < img.height; ++y) {
        for (int x = 0; x < img.width; ++x) {
            for (int c = 0; c < 3; ++c) {
                out.rgb[(static_cast<size_t>(y) * img.width + x) * 3 + c] =
                    img.rgb[(static_cast<size_t>(y) * img.width + (img.width - 1 - x)) * 3 + c];
            }
        }
    }
    return out;
}

// Copies the w x h window of `src` centred on (cx, cy), clamped inside it, to (dx, dy) of `dst`.
void paste_crop(const Image8& src, int cx, int cy, int w, int h, Image8& dst, int dx, int dy) {
    const int x0 = std::clamp(cx - w / 2, 0, std::max(0, src.width - w));
    const int y0 = std::clamp(cy - h / 2, 0, std::max(0, src.height - h));
    for (int y = 0; y < h && y0 + y < src.height; ++y) {
        for (int x = 0; x < w && x0 + x < src.width; ++x) {
            for (int c = 0; c < 3; ++c) {
                dst.rgb[(static_cast<size_t>(dy + y) * dst.width + dx + x) * 3 + c] =
                    src.rgb[(static_cast<size_t>(y0 + y) * src.width + x0 + x) * 3 + c];
            }
        }
    }
}

// Where the colour-speckle index is measured, as fractions of the picture in lenslab's
// orientation (POV-Ray's comes in mirrored), placed for the report scene's camera at 900 x 900:
// a disc well inside the glass sphere's image (centre (646, 432), radius 109 there), and one
// around the sphere's caustic on the floor and its fringe, clear of the sphere above it.
PixelDisc report_disc(double cx, double cy, double r, const Image8& image) {
    return {cx / 900 * image.width, cy / 900 * image.height, r / 900 * image.width};
}
PixelDisc glass_disc(const Image8& image) { return report_disc(646, 432, 80, image); }
PixelDisc caustic_disc(const Image8& image) { return report_disc(672, 550, 18, image); }

void measure_speckle(Side& side, const Image8& image) {
    side.speckle_glass = colour_speckle(image, glass_disc(image));
    side.speckle_caustic = colour_speckle(image, caustic_disc(image));
}

// One row per renderer: a label bar above the crops of the lens caustic and of the glass
// sphere's caustic. The windows are fractions of the image, placed for the report scene's
// camera in lenslab's (right-handed) orientation; POV-Ray's picture comes in mirrored.
Image8 side_by_side(const Image8& povray_mirrored, const Image8& lenslab,
                    const std::string& povray_label, const std::string& lenslab_label) {
    const int w = lenslab.width, h = lenslab.height;
    const int crop_w = std::max(1, w / 3), crop_h = std::max(1, w * 220 / 900);
    struct Centre {
        double x, y;
    };
    const Centre lens{215.0 / 900, 548.0 / 900}, sphere{672.0 / 900, 548.0 / 900};
    Image8 out;
    out.width = 2 * crop_w;
    // Large letters where both labels fit; small images get small (and maybe clipped) ones.
    const int widest = std::max(text_width(povray_label, 1), text_width(lenslab_label, 1));
    const int scale = 2 * widest <= out.width ? 2 : 1;
    const int bar = kGlyphHeight * scale + 6;
    out.height = 2 * (bar + crop_h);
    out.rgb.assign(static_cast<size_t>(out.width) * out.height * 3, 0);
    const unsigned char white[3] = {255, 255, 255};
    const Image8* rows[2] = {&povray_mirrored, &lenslab};
    const std::string* labels[2] = {&povray_label, &lenslab_label};
    for (int r = 0; r < 2; ++r) {
        const int top = r * (bar + crop_h);
        const int text_w = text_width(*labels[r], scale);
        draw_text(out, std::max(2, (out.width - text_w) / 2), top + 3, *labels[r], white, scale);
        paste_crop(*rows[r], static_cast<int>(lens.x * w), static_cast<int>(lens.y * h), crop_w,
                   crop_h, out, 0, top + bar);
        paste_crop(*rows[r], static_cast<int>(sphere.x * w), static_cast<int>(sphere.y * h), crop_w,
                   crop_h, out, crop_w, top + bar);
    }
    return out;
}

std::string photons_short(int64_t n) {
    if (n >= 1000000 && n % 100000 == 0) return fixed(n / 1e6, n % 1000000 ? 1 : 0) + "M";
    if (n >= 1000 && n % 1000 == 0) return std::to_string(n / 1000) + "k";
    return std::to_string(n);
}

std::string ratio(double lenslab, double povray) {
    return povray > 0 ? fixed(lenslab / povray, 2) : "";
}

std::string markdown(const PovrayBenchArgs& a, const Side& pov, const Side& ll,
                     const std::string& load_before, const std::string& load_after) {
    std::ostringstream md;
    const std::string pov_name =
        "POV-Ray " + (pov.version.empty() ? std::string("3.7") : pov.version);
    md << "| | " << pov_name << " | lenslab | lenslab / POV-Ray |\n| --- | ---: | ---: | ---: |\n";
    const double pm = median(pov.seconds), lm = median(ll.seconds);
    md << "| wall time (same run, alternating, median of " << a.repeats << ") | " << fixed(pm, 2)
       << " s | " << fixed(lm, 2) << " s | " << ratio(lm, pm) << " |\n";
    const auto [pmin, pmax] = std::minmax_element(pov.seconds.begin(), pov.seconds.end());
    const auto [lmin, lmax] = std::minmax_element(ll.seconds.begin(), ll.seconds.end());
    md << "| wall time, fastest - slowest run | " << fixed(*pmin, 2) << " - " << fixed(*pmax, 2)
       << " s | " << fixed(*lmin, 2) << " - " << fixed(*lmax, 2) << " s | |\n";
    const auto count = [](const std::optional<int64_t>& n) {
        return n ? grouped(*n) : std::string("-");
    };
    md << "| caustic photons stored | " << count(pov.caustic_stored) << " | "
       << count(ll.caustic_stored) << " | "
       << (pov.caustic_stored && ll.caustic_stored ? ratio(static_cast<double>(*ll.caustic_stored),
                                                           static_cast<double>(*pov.caustic_stored))
                                                   : "")
       << " |\n";
    md << "| colour speckle inside the glass sphere | " << fixed(pov.speckle_glass, 4) << " | "
       << fixed(ll.speckle_glass, 4) << " | " << ratio(ll.speckle_glass, pov.speckle_glass)
       << " |\n";
    md << "| colour speckle in the sphere's caustic | " << fixed(pov.speckle_caustic, 4) << " | "
       << fixed(ll.speckle_caustic, 4) << " | " << ratio(ll.speckle_caustic, pov.speckle_caustic)
       << " |\n";
    md << "| direct photons stored | - (ray traced) | " << count(ll.direct_stored) << " | |\n";
    md << "| photons shot (POV-Ray) / emitted (lenslab) | " << count(pov.shot) << " | "
       << count(ll.shot) << " | |\n\n";
    md << "Each run's wall time, in order (s): POV-Ray";
    for (double s : pov.seconds) md << " " << fixed(s, 2);
    md << "; lenslab";
    for (double s : ll.seconds) md << " " << fixed(s, 2);
    md << ".\n\nSettings: " << a.width << "x" << a.height << ", 1 sample per pixel, " << a.threads
       << " threads, " << grouped(a.photons) << " photons requested, gather radius " << a.radius
       << ", at most " << a.gather_max
       << " photons per estimate. Colour speckle: each pixel's chroma (R - G, G - B) against "
          "its 5 x 5 neighbourhood's mean, averaged in a disc (image/colour_speckle.h; on the "
          "900 x 900 picture, radius 80 about (646, 432) in the glass, radius 18 about "
          "(672, 550) in the caustic, POV-Ray's picture mirrored first).\n\nCommands (run "
          "alternately, "
       << a.repeats << (a.repeats == 1 ? " run" : " runs")
       << " of each, in the output folder):\n\n```\n"
       << shell_command_line(pov.command) << "\n"
       << shell_command_line(ll.command) << "\n```\n\n";
    std::string cpu = first_line_matching("/proc/cpuinfo", "model name");
    md << "Machine: nproc " << sysconf(_SC_NPROCESSORS_ONLN) << ", CPU "
       << (cpu.empty() ? std::string("unknown") : cpu) << "; load average (1, 5, 15 min) "
       << load_before << " before the runs, " << load_after << " after.\n";
    return md.str();
}

void check_file(const std::string& path, const std::string& option) {
    std::error_code ec;
    if (!fs::is_regular_file(path, ec)) {
        throw BenchError(option + " " + path +
                         ": no such file (run from the lenslab source folder, or give " + option +
                         ")");
    }
}

int run_bench(const PovrayBenchArgs& a) {
    std::string povray = a.povray.empty() ? find_on_path("povray") : a.povray;
    if (povray.empty()) {
        throw BenchError(
            "POV-Ray is not installed (no 'povray' on PATH): install it with "
            "apt-get install povray, or give its path with --povray");
    }
    if (!is_executable_file(povray)) {
        throw BenchError("--povray " + povray +
                         ": no such executable file (install POV-Ray with "
                         "apt-get install povray)");
    }
    check_file(a.pov, "--pov");
    check_file(a.scene, "--scene");
    create_output_directory(a.out_dir);  // before the runs, not after them
    const fs::path dir = fs::absolute(a.out_dir);
    const fs::path pov_png = dir / "povray.png", ll_png = dir / "lenslab.png";
    // POV-Ray writes its image in place, so it draws into a temporary name that is renamed
    // once it has finished: povray.png is never half written.
    const std::string pov_tmp = temporary_path_for(pov_png.string());
    const fs::path log = temporary_path_for((dir / "child.log").string());

    Side pov, ll;
    pov.command = {povray,
                   "+I" + fs::absolute(a.pov).string(),
                   "+O" + pov_tmp,
                   "+FN",
                   "+W" + std::to_string(a.width),
                   "+H" + std::to_string(a.height),
                   "-A",
                   "+WT" + std::to_string(a.threads),
                   "-D",
                   "-P",
                   "Declare=PhotonCount=" + std::to_string(a.photons),
                   "Declare=GatherRadius=" + number(a.radius),
                   "Declare=GatherMax=" + std::to_string(a.gather_max)};
    // Our own executable, so lenslab is timed as a whole process exactly as POV-Ray is.
    ll.command = {fs::read_symlink("/proc/self/exe").string(),
                  "render",
                  fs::absolute(a.scene).string(),
                  "-o",
                  ll_png.string(),
                  "--width",
                  std::to_string(a.width),
                  "--height",
                  std::to_string(a.height),
                  "--spp",
                  "1",
                  "--threads",
                  std::to_string(a.threads),
                  "--integrator",
                  std::string(integrators::kPhotonMap),
                  "--caustic-photons",
                  std::to_string(a.photons),
                  "--radius",
                  number(a.radius),
                  "--max-photons-per-estimate",
                  std::to_string(a.gather_max),
                  "--tone-map",
                  a.tone_map};

    const std::string load_before = load_average();
    std::fprintf(stderr,
                 "POV-Ray (%s) and lenslab, %d run(s) of each, alternating; load average %s\n",
                 povray.c_str(), a.repeats, load_before.c_str());
    const std::regex pov_stored(R"(Surface photons stored:\s+(\d+))");
    const std::regex pov_shot(R"(Number of photons shot:\s+(\d+))");
    const std::regex pov_version(R"(Ray Tracer Version (\d+\.\d+(\.\d+)*))");
    const std::regex ll_photons(
        R"(photons: (\d+) emitted \((\d+) aimed[^)]*\), (\d+) direct \+ (\d+) caustic stored)");
    for (int i = 0; i < a.repeats; ++i) {
        const ChildResult p = run_child(pov.command, dir, log);
        check_ran(p, "POV-Ray");
        std::error_code ec;
        fs::rename(pov_tmp, pov_png, ec);
        if (ec) throw BenchError("POV-Ray wrote no image " + pov_tmp + ": " + ec.message());
        pov.seconds.push_back(p.seconds);
        pov.last_output = p.output;

        const ChildResult l = run_child(ll.command, dir, log);
        check_ran(l, "lenslab");
        ll.seconds.push_back(l.seconds);
        ll.last_output = l.output;
        std::fprintf(stderr, "  run %d/%d: POV-Ray %.2f s, lenslab %.2f s\n", i + 1, a.repeats,
                     p.seconds, l.seconds);
    }
    const std::string load_after = load_average();
    pov.caustic_stored = match_count(pov.last_output, pov_stored);
    pov.shot = match_count(pov.last_output, pov_shot);
    std::smatch version;
    if (std::regex_search(pov.last_output, version, pov_version)) pov.version = version[1].str();
    ll.shot = match_count(ll.last_output, ll_photons, 1);
    ll.direct_stored = match_count(ll.last_output, ll_photons, 3);
    ll.caustic_stored = match_count(ll.last_output, ll_photons, 4);
    // The commands as a user would type them: POV-Ray's image under its final name.
    pov.command[2] = "+O" + pov_png.string();
    pov.command[0] = "povray";
    ll.command[0] = "lenslab";
    write_text_atomically((dir / "povray.log").string(), pov.last_output);
    write_text_atomically((dir / "lenslab.log").string(), ll.last_output);

    const Image8 pov_img = read_png(pov_png.string()), ll_img = read_png(ll_png.string());
    if (pov_img.width != ll_img.width || pov_img.height != ll_img.height) {
        throw BenchError("the two images differ in size: POV-Ray " + std::to_string(pov_img.width) +
                         "x" + std::to_string(pov_img.height) + ", lenslab " +
                         std::to_string(ll_img.width) + "x" + std::to_string(ll_img.height));
    }
    measure_speckle(pov, mirrored(pov_img));
    measure_speckle(ll, ll_img);
    const std::string amount = photons_short(a.photons) + " photons, r " + number(a.radius);
    const std::string pov_label =
        "POV-Ray, mirrored: " + amount + ", " + fixed(median(pov.seconds), 2) + " s";
    const std::string ll_label = "lenslab: " + amount + ", " + fixed(median(ll.seconds), 2) + " s";
    write_png_image(side_by_side(mirrored(pov_img), ll_img, pov_label, ll_label),
                    (dir / "caustics_side_by_side.png").string());

    const std::string table = markdown(a, pov, ll, load_before, load_after);
    write_text_atomically((dir / "povray.md").string(), table);
    std::printf("%s\nwrote %s/povray.md, povray.png, lenslab.png, caustics_side_by_side.png\n",
                table.c_str(), dir.c_str());
    return 0;
}

}  // namespace

Action add_bench_povray_command(CLI::App& bench) {
    auto args = std::make_shared<PovrayBenchArgs>();
    CLI::App* cmd = bench.add_subcommand("povray",
                                         "POV-Ray 3.7 and lenslab on the report scene, "
                                         "alternately: wall times, photons stored, images");
    cmd->add_option("--povray", args->povray, "POV-Ray executable (default: povray on PATH)");
    cmd->add_option("--pov", args->pov, "POV-Ray scene")->capture_default_str();
    cmd->add_option("--scene", args->scene, "lenslab scene")->capture_default_str();
    cmd->add_option("-o,--output", args->out_dir, "Folder for povray.md and the images")
        ->capture_default_str();
    cmd->add_option("--photons", args->photons,
                    "Photons: POV-Ray's PhotonCount, lenslab's --caustic-photons")
        ->capture_default_str()
        ->check(whole_number<int64_t>())
        ->check(CLI::Range(int64_t{1}, int64_t{1} << 32));
    cmd->add_option("--radius", args->radius, "Gather radius of both")
        ->capture_default_str()
        ->check(CLI::PositiveNumber);
    cmd->add_option(
           "--gather-max", args->gather_max,
           "Most photons per estimate: POV-Ray's GatherMax, lenslab's --max-photons-per-estimate")
        ->capture_default_str()
        ->check(whole_number<int>())
        ->check(CLI::Range(1, 1000000));
    cmd->add_option("--repeats", args->repeats, "Runs of each (the median wall time is kept)")
        ->capture_default_str()
        ->check(whole_number<int>())
        ->check(CLI::Range(1, 100));
    cmd->add_option("--threads", args->threads, "Render threads of both")
        ->capture_default_str()
        ->check(whole_number<int>())
        ->check(CLI::Range(1, 1024));
    cmd->add_option("--width", args->width, "Image width")
        ->capture_default_str()
        ->check(whole_number<int>())
        ->check(CLI::Range(16, kMaxImageSide));
    cmd->add_option("--height", args->height, "Image height")
        ->capture_default_str()
        ->check(whole_number<int>())
        ->check(CLI::Range(16, kMaxImageSide));
    cmd->add_option("--tone-map", args->tone_map,
                    "lenslab's tone map: clip (as POV-Ray's PNG) or log (the caustics' "
                    "highlights on a log scale: their rings and fringe show)")
        ->capture_default_str()
        ->check(CLI::IsMember(kToneMapNames));
    return [args] {
        try {
            return run_bench(*args);
        } catch (const BenchError& e) {
            std::cerr << "lenslab: error: " << e.what() << "\n";
            return 1;
        }
    };
}

}  // namespace lenslab::cli
