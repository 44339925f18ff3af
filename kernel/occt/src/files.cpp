// Writing and reading solids through OpenCASCADE: STEP (AP214) and the native .brep text.

#include "ratbez/occt/files.hpp"

#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <Interface_Static.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_PrinterOStream.hxx>
#include <Message_ProgressIndicator.hxx>
#include <STEPControl_Reader.hxx>
#include <STEPControl_StepModelType.hxx>
#include <STEPControl_Writer.hxx>
#include <Standard_Failure.hxx>

#include <algorithm>
#include <array>
#include <exception>
#include <filesystem>
#include <fstream>
#include <istream>
#include <mutex>
#include <sstream>
#include <streambuf>

#include "ratbez/error.hpp"
#include "ratbez/occt/shape_import.hpp"
#include "ratbez/occt/topology.hpp"
#include "ratbez/output_file.hpp"

namespace ratbez::occt {
namespace {

// STEPControl_Writer prints statistics through the default messenger's stdout printer. Detach the
// ostream printers while writing and put them back afterwards, so the caller's own OCCT messages are
// not silenced for good (SETUP-NOTES). OCCT's messenger is global: one writer at a time.
class QuietMessenger {
public:
    QuietMessenger() : lock_(mutex()) {
        const Handle(Message_Messenger)& messenger = Message::DefaultMessenger();
        for (Message_SequenceOfPrinters::Iterator it(messenger->Printers()); it.More(); it.Next())
            if (it.Value()->IsKind(STANDARD_TYPE(Message_PrinterOStream))) removed_.Append(it.Value());
        messenger->RemovePrinters(STANDARD_TYPE(Message_PrinterOStream));
    }
    ~QuietMessenger() {
        const Handle(Message_Messenger)& messenger = Message::DefaultMessenger();
        for (Message_SequenceOfPrinters::Iterator it(removed_); it.More(); it.Next()) messenger->AddPrinter(it.Value());
    }
    QuietMessenger(const QuietMessenger&) = delete;
    QuietMessenger& operator=(const QuietMessenger&) = delete;

private:
    static std::mutex& mutex() {
        static std::mutex m;
        return m;
    }
    std::lock_guard<std::mutex> lock_;
    Message_SequenceOfPrinters removed_;
};

// The caller's Progress as OpenCASCADE's readers call it, from code our exceptions must not cross: the
// first exception the callback throws (Ctrl-C in Python) is kept, every call from then on answers
// "stopped" so the reader winds down, and rethrow_if_stopped() throws it once the reader has returned.
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

// The file as OpenCASCADE's STEP parser reads it (XSControl_Reader::ReadStream), kBlock bytes at a time,
// reporting the share of the file read, times `scale`, at each refill: the parse itself has no progress
// hook in OCCT 7.6 (a 39 MB file parsed for 9 s unpolled). Once stopped the stream simply ends (the parser
// sees a truncated file), so nothing is thrown through OpenCASCADE's parser.
class PolledFileBuffer : public std::streambuf {
public:
    PolledFileBuffer(const std::string& path, CapturedProgress& progress, double scale)
        : file_(path, std::ios::binary), progress_(progress), scale_(scale) {
        std::error_code error;
        size_ = std::max<double>(1.0, static_cast<double>(std::filesystem::file_size(path, error)));
    }

protected:
    int_type underflow() override {
        if (gptr() < egptr()) return traits_type::to_int_type(*gptr());
        if (!progress_.report(scale_ * std::min(read_ / size_, 1.0))) return traits_type::eof();
        file_.read(block_.data(), static_cast<std::streamsize>(block_.size()));
        const std::streamsize count = file_.gcount();
        if (count <= 0) return traits_type::eof();
        read_ += static_cast<double>(count);
        setg(block_.data(), block_.data(), block_.data() + count);
        return traits_type::to_int_type(*gptr());
    }

private:
    static constexpr std::size_t kBlock = 16384;
    std::ifstream file_;
    CapturedProgress& progress_;
    double scale_;
    std::array<char, kBlock> block_{};
    double size_ = 1, read_ = 0;
};

// OpenCASCADE's readers poll their progress indicator's UserBreak(): there the reader's position, mapped
// to [from, to], is reported, and a stop breaks the reader off.
class PolledIndicator : public Message_ProgressIndicator {
public:
    PolledIndicator(CapturedProgress& progress, double from, double to) : progress_(progress), from_(from), to_(to) {}
    Standard_Boolean UserBreak() override { return !progress_.report(from_ + (to_ - from_) * GetPosition()); }
    void Show(const Message_ProgressScope&, const Standard_Boolean) override {}

private:
    CapturedProgress& progress_;
    double from_, to_;
};

void require_readable(const std::string& path) {
    std::error_code error;
    require(std::filesystem::exists(path, error), "path", "'" + path + "' does not exist");
    require(std::filesystem::is_regular_file(path, error), "path", "'" + path + "' is not a file");
    require(std::ifstream(path).good(), "path", "cannot read '" + path + "'");
}

// The one solid of the shape read from `path`, conversion errors blamed on the file.
Solid solid_from_file(const TopoDS_Shape& shape, const std::string& path, const Progress& progress) {
    const Progress second_half = [&](double fraction) {
        if (progress) progress(0.5 + 0.5 * fraction);
    };
    try {
        return from_occt(shape, second_half);
    } catch (const Error& e) {
        throw Error("path", "'" + path + "': " + std::string(e.reason()));
    }
}

}  // namespace

// Both writers go through output_file.hpp: the path is checked and a temporary file made first (cheap
// checks before the conversion), OpenCASCADE writes that file by name, and it is renamed over the target.
void write_step(const Solid& solid, const std::string& path, const ConvertOptions& options) {
    output::write_file_by_name(path, [&](const std::string& name) {
        const TopoDS_Solid shape = to_occt(solid, options);
        QuietMessenger quiet;
        try {
            STEPControl_Writer writer;  // its constructor initialises the STEP statics (STEPControl_Controller::Init)
            Interface_Static::SetCVal("write.step.schema", "AP214IS");
            require(writer.Transfer(shape, STEPControl_AsIs) == IFSelect_RetDone, "solid",
                    "OpenCASCADE could not translate it to STEP");
            require(writer.Write(name.c_str()) == IFSelect_RetDone, "path", "cannot write '" + path + "'");
        } catch (const Standard_Failure& failure) {
            throw Error("path", "writing STEP to '" + path + "' failed: " + failure.GetMessageString());
        }
    });
}

void write_brep(const Solid& solid, const std::string& path, const ConvertOptions& options) {
    output::write_file_by_name(path, [&](const std::string& name) {
        require(BRepTools::Write(to_occt(solid, options), name.c_str()), "path", "cannot write '" + path + "'");
    });
}

std::string brep_string(const Solid& solid, const ConvertOptions& options) {
    std::ostringstream out;
    // BRepTools::Write(shape, file) starts the file with this line (the Draw shape tag) and the stream
    // version does not; write it so the string is exactly the file's text. Both readers accept either.
    out << "DBRep_DrawableShape\n";
    BRepTools::Write(to_occt(solid, options), out);
    return out.str();
}

Solid read_step(const std::string& path, const Progress& progress) {
    require_readable(path);
    TopoDS_Shape shape;
    {
        QuietMessenger quiet;
        try {
            // The parse is the first quarter of the progress, the translation the second (solid_from_file
            // the second half).
            CapturedProgress captured(progress);
            STEPControl_Reader reader;
            PolledFileBuffer buffer(path, captured, 0.25);
            std::istream stream(&buffer);
            const IFSelect_ReturnStatus parsed = reader.ReadStream(path.c_str(), stream);
            captured.rethrow_if_stopped();
            require(parsed == IFSelect_RetDone, "path", "'" + path + "' is not a readable STEP file");
            Handle(PolledIndicator) indicator = new PolledIndicator(captured, 0.25, 0.5);
            const int transferred = reader.TransferRoots(indicator->Start());
            captured.rethrow_if_stopped();
            require(transferred > 0, "path", "'" + path + "' holds no shape OpenCASCADE can translate");
            shape = reader.OneShape();
        } catch (const Standard_Failure& failure) {
            throw Error("path", "reading STEP from '" + path + "' failed: " + failure.GetMessageString());
        }
    }
    return solid_from_file(shape, path, progress);
}

Solid read_brep(const std::string& path, const Progress& progress) {
    require_readable(path);
    {
        // BRepTools::Read prints to stdout when a file is not .brep: look at its first line first. A .brep file
        // starts with OCCT's "CASCADE Topology V<n>" or with BRepTools::Write's Draw tag line before it.
        std::ifstream in(path);
        std::string first;
        std::getline(in, first);
        require(first.rfind("DBRep_DrawableShape", 0) == 0 || first.rfind("CASCADE Topology V", 0) == 0, "path",
                "'" + path + "' is not a readable .brep file (it does not start with OpenCASCADE's header)");
    }
    TopoDS_Shape shape;
    try {
        CapturedProgress captured(progress);
        Handle(PolledIndicator) indicator = new PolledIndicator(captured, 0, 0.5);
        const bool read = BRepTools::Read(shape, path.c_str(), BRep_Builder(), indicator->Start());
        captured.rethrow_if_stopped();
        require(read && !shape.IsNull(), "path", "'" + path + "' is not a readable .brep file");
    } catch (const Standard_Failure& failure) {
        throw Error("path", "reading .brep from '" + path + "' failed: " + failure.GetMessageString());
    }
    return solid_from_file(shape, path, progress);
}

}  // namespace ratbez::occt
