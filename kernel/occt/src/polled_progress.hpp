#pragma once
// The caller's Progress inside OpenCASCADE's algorithms, which poll it (files.cpp's readers, check.cpp's BOP
// analysis). Internal to kernel/occt.

#include <Message_ProgressIndicator.hxx>
#include <Message_ProgressScope.hxx>

#include <exception>

#include "ratbez/progress.hpp"

namespace ratbez::occt::detail {

// The caller's Progress as OpenCASCADE's algorithms call it (its file readers, the BOP analysis), from code our
// exceptions must not cross: the first exception the callback throws (Ctrl-C in Python) is kept, every call from
// then on answers "stopped" so the algorithm winds down, and rethrow_if_stopped() throws it once it has returned.
class CapturedProgress {
public:
    explicit CapturedProgress(const Progress& progress) : progress_(progress) {}
    // Reports `fraction`; false once the callback has thrown (now or before).
    bool report(double fraction) {
        if (progress_ && !stopped_) {
            try {
                progress_(fraction);
            } catch (...) {
                stopped_ = std::current_exception();
            }
        }
        return stopped_ == nullptr;
    }
    void rethrow_if_stopped() const {
        if (stopped_) std::rethrow_exception(stopped_);
    }

private:
    const Progress& progress_;
    std::exception_ptr stopped_;
};

// OpenCASCADE's algorithms poll their progress indicator's UserBreak(): there the position, mapped to [from, to],
// is reported, and a stop breaks the algorithm off.
class PolledIndicator : public Message_ProgressIndicator {
public:
    PolledIndicator(CapturedProgress& progress, double from, double to) : progress_(progress), from_(from), to_(to) {}
    Standard_Boolean UserBreak() override { return !progress_.report(from_ + (to_ - from_) * GetPosition()); }
    void Show(const Message_ProgressScope&, const Standard_Boolean) override {}

private:
    CapturedProgress& progress_;
    double from_, to_;
};

}  // namespace ratbez::occt::detail
