#include "interrupt_cancels.h"

#include <csignal>

#include "render/render_control.h"

namespace lenslab::cli {

namespace {

RenderControl* g_interrupted_control = nullptr;

extern "C" void cancel_on_interrupt(int) {
    // An atomic store: safe in a signal handler.
    if (g_interrupted_control) g_interrupted_control->cancel();
}

}  // namespace

InterruptCancels::InterruptCancels(RenderControl& control) {
    g_interrupted_control = &control;
    struct sigaction action {};
    action.sa_handler = cancel_on_interrupt;
    action.sa_flags = SA_RESETHAND;
    sigaction(SIGINT, &action, nullptr);
}

InterruptCancels::~InterruptCancels() { release(); }

void InterruptCancels::release() {
    if (!m_active) return;
    m_active = false;
    signal(SIGINT, SIG_DFL);
    g_interrupted_control = nullptr;
}

}  // namespace lenslab::cli
