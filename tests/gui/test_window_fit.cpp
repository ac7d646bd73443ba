// The window on a small or scaled screen (issue 41): run on a 1600 x 1000 screen at
// QT_SCALE_FACTOR=1.5 (tests/CMakeLists.txt), 1067 x 667 logical pixels, the window opens
// inside the screen's available area with its status line on the screen, and with its docks
// at their smallest it would fit a screen with room for a title bar and a task bar.

#include <QStatusBar>
#include <QtTest>

#include "main_window.h"

using lenslab::gui::MainWindow;

class TestWindowFit : public QObject {
    Q_OBJECT

private slots:
    void the_window_fits_a_1000_pixel_screen_at_1_5x() {
        QCOMPARE(qgetenv("QT_SCALE_FACTOR"), QByteArray("1.5"));
        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        const QRect room = w.screen()->availableGeometry();
        QVERIFY2(room.height() < 700, qPrintable(QString::number(room.height())));
        const auto text = [](const QRect& r) {
            return QString("%1,%2 %3x%4").arg(r.x()).arg(r.y()).arg(r.width()).arg(r.height());
        };
        QVERIFY2(room.contains(w.frameGeometry()),
                 qPrintable(text(w.frameGeometry()) + " in " + text(room)));
        const QRect status(w.statusBar()->mapToGlobal(QPoint(0, 0)), w.statusBar()->size());
        QVERIFY2(room.contains(status), qPrintable(text(status) + " in " + text(room)));
        // At its smallest: 667 logical pixels less about 60 for a title bar and a task bar.
        const QSize smallest = w.minimumSizeHint().expandedTo(w.minimumSize());
        QVERIFY2(smallest.height() <= 600 && smallest.width() <= room.width(),
                 qPrintable(QString("%1 x %2").arg(smallest.width()).arg(smallest.height())));
    }
};

QTEST_MAIN(TestWindowFit)
#include "test_window_fit.moc"
