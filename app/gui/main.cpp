// lenslab-gui [SCENE]: the desktop editor.
// lenslab-gui --screenshot FILE [--passes N] [SCENE]: render N passes, save a grab of the
// whole window to FILE and exit (for documentation and checks). --measure first measures
// the detectors and shows the selected one's map. --view section shows the 2-D section view
// (of the --select'ed lens) instead of the 3-D view; its screenshot does not wait for passes.

#include <QApplication>
#include <QCommandLineParser>
#include <QFileInfo>
#include <QSaveFile>
#include <QTimer>
#include <cstdio>
#include <memory>

#include "detector_dock.h"
#include "main_window.h"
#include "render_controller.h"
#include "scene_tree.h"
#include "util/output_path.h"

int main(int argc, char** argv) {
    QApplication app(argc, argv);
    QApplication::setApplicationName("lenslab-gui");
    QApplication::setOrganizationName("lenslab");
    QCommandLineParser parser;
    parser.setApplicationDescription("lenslab: edit a scene and watch light go through lenses");
    parser.addHelpOption();
    parser.addPositionalArgument("scene",
                                 "Scene file to open (default: the built-in default scene)");
    QCommandLineOption screenshot("screenshot",
                                  "Render, save a grab of the window to FILE and exit.", "FILE");
    QCommandLineOption passes("passes", "Passes to render before --screenshot grabs (default 8).",
                              "N", "8");
    QCommandLineOption select(
        "select", "Select an element first, by JSON pointer (e.g. /objects/1).", "POINTER");
    parser.addOption(screenshot);
    parser.addOption(passes);
    QCommandLineOption measure(
        "measure",
        "Measure the detectors and show the detector dock (with --screenshot: before the grab).");
    QCommandLineOption view("view", "The view in front: 3d (default) or section.", "VIEW", "3d");
    parser.addOption(select);
    parser.addOption(measure);
    parser.addOption(view);
    parser.process(app);

    lenslab::gui::MainWindow window;
    const QStringList args = parser.positionalArguments();
    if (!args.isEmpty()) {
        QString error;
        if (!window.open_file(args.first(), &error)) {
            std::fprintf(stderr, "lenslab-gui: error: %s\n", qPrintable(error));
            if (parser.isSet(screenshot)) return 1;
            // The dialog File ▸ Open shows, over the default scene: a status-bar message
            // went unseen under other text.
            window.show_open_error(error);
        }
    }
    if (parser.isSet(select)) window.tree()->select_pointer(parser.value(select));
    if (!window.show_view(parser.value(view))) {
        std::fprintf(stderr, "lenslab-gui: error: --view must be 3d or section, got '%s'\n",
                     qPrintable(parser.value(view)));
        return 2;
    }
    const bool section_view = parser.value(view) == "section";
    // Grabs for the documentation have one size whatever the screen or the last session.
    if (parser.isSet(screenshot)) window.resize(1280, 800);
    window.show();
    bool measuring = parser.isSet(measure);
    if (measuring) {
        window.detector_dock()->raise();
        QObject::connect(window.detector_dock(), &lenslab::gui::DetectorDock::measured, &window,
                         [&] { measuring = false; });
        window.detector_dock()->measure();
        if (!window.detector_dock()->is_measuring()) measuring = false;  // no detector
    }

    if (parser.isSet(screenshot)) {
        bool ok = false;
        const int wanted = parser.value(passes).toInt(&ok);
        if (!ok || wanted < 1) {
            std::fprintf(stderr, "lenslab-gui: error: --passes must be a whole number >= 1\n");
            return 2;
        }
        const QString file = parser.value(screenshot);
        try {
            lenslab::check_output_file(file.toStdString());  // before the render, not after
        } catch (const lenslab::FileWriteError& e) {
            std::fprintf(stderr, "lenslab-gui: error: %s\n", e.what());
            return 1;
        }
        // The handlers run in app.exec(), after this block: they hold copies of its locals.
        // Once: frames queued before the exit must not write the file again.
        const auto grabbed = std::make_shared<bool>(false);
        const auto grab = [file, grabbed, &window] {
            if (*grabbed) return;
            *grabbed = true;
            // Atomic, like every file lenslab writes.
            QSaveFile out(file);
            const bool saved = out.open(QIODevice::WriteOnly) &&
                               window.grab().toImage().save(
                                   &out, QFileInfo(file).suffix().toLatin1().constData()) &&
                               out.commit();
            std::fprintf(saved ? stdout : stderr,
                         saved ? "wrote %s\n" : "lenslab-gui: error: cannot write %s\n",
                         qPrintable(file));
            QApplication::exit(saved ? 0 : 1);
        };
        if (section_view && !measuring) {
            // The section is drawn from the scene, not from rendered passes.
            QTimer::singleShot(200, &window, grab);
        } else {
            QObject::connect(window.renderer(), &lenslab::gui::RenderController::frame_ready,
                             &window, [wanted, grab, &measuring, &window](const QImage&, int done) {
                                 if (done < wanted || measuring) return;
                                 // Let the frame reach the viewport and the status bar first.
                                 QTimer::singleShot(50, &window, grab);
                             });
        }
        QTimer::singleShot(600000, &app, [] {
            std::fprintf(stderr, "lenslab-gui: error: --screenshot timed out\n");
            QApplication::exit(1);
        });
    }
    return app.exec();
}
