// Writing solids through OpenCASCADE: STEP (AP214) and the native .brep text.

#include "ratbez/occt/files.hpp"

#include <BRepTools.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <Interface_Static.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_PrinterOStream.hxx>
#include <STEPControl_StepModelType.hxx>
#include <STEPControl_Writer.hxx>
#include <Standard_Failure.hxx>

#include <mutex>
#include <sstream>

#include "ratbez/error.hpp"
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

}  // namespace ratbez::occt
