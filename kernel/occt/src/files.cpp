// Writing and reading solids through OpenCASCADE: STEP (AP214) and the native .brep text.

#include "ratbez/occt/files.hpp"

#include <BRepTools.hxx>
#include <BinTools.hxx>
#include <TopoDS_Iterator.hxx>
#include <Standard_OutOfMemory.hxx>
#include <BRep_Builder.hxx>
#include <TopoDS_Compound.hxx>
#include <TopTools_MapOfShape.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <Interface_Static.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_PrinterOStream.hxx>
#include <Message_ProgressIndicator.hxx>
#include <STEPCAFControl_Reader.hxx>
#include <STEPControl_Reader.hxx>
#include <Resource_Manager.hxx>
#include <ShapeAlgo.hxx>
#include <ShapeAlgo_AlgoContainer.hxx>
#include <ShapeAlgo_ToolContainer.hxx>
#include <ShapeFix_Face.hxx>
#include <ShapeFix_Shape.hxx>
#include <ShapeProcess_Context.hxx>
#include <TDF_Label.hxx>
#include <TDF_LabelSequence.hxx>
#include <TDataStd_Name.hxx>
#include <TDocStd_Document.hxx>
#include <TopExp_Explorer.hxx>
#include <TopLoc_Location.hxx>
#include <XCAFApp_Application.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>
#include <STEPControl_StepModelType.hxx>
#include <STEPCAFControl_Writer.hxx>
#include <TCollection_ExtendedString.hxx>
#include <Standard_Failure.hxx>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <span>
#include <array>
#include <exception>
#include <filesystem>
#include <fstream>
#include <istream>
#include <mutex>
#include <numeric>
#include <optional>
#include <sstream>
#include <streambuf>
#include <utility>

#include "child_process.hpp"
#include "polled_progress.hpp"
#include "file_prescan.hpp"
#include "self_consistency.hpp"
#include "ratbez/error.hpp"
#include "ratbez/occt/shape_import.hpp"
#include "ratbez/occt/topology.hpp"
#include "ratbez/output_file.hpp"

namespace ratbez::occt {
namespace {

using detail::CapturedProgress;
using detail::PolledIndicator;

// STEPControl_Writer prints statistics through the default messenger's stdout printer. Detach the
// ostream printers while writing and put them back afterwards, so the caller's own OCCT messages are
// not silenced for good (SETUP-NOTES). OCCT's messenger is global: one writer at a time.
// The readers run in a child process of one thread (child_process.hpp): there the messenger is the child's
// own, and the lock is not taken (a thread of the parent may have held it when the child was forked, and
// a reader's Progress, called by the parent, may itself write or read without meeting a held lock).
class QuietMessenger {
public:
    enum class Lock { take, skip_in_child };
    explicit QuietMessenger(Lock lock = Lock::take) {
        if (lock == Lock::take) lock_ = std::unique_lock<std::mutex>(mutex());
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
    std::unique_lock<std::mutex> lock_;
    Message_SequenceOfPrinters removed_;
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

void require_readable(const std::string& path) {
    // The system's reason where it has one: a path it may not look into is not a path that does not exist.
    std::error_code error;
    const bool exists = std::filesystem::exists(path, error);
    require(!error, "path", [&] { return "cannot read '" + path + "': " + error.message(); });
    require(exists, "path", "'" + path + "' does not exist");
    require(std::filesystem::is_regular_file(path, error), "path", "'" + path + "' is not a file");
    errno = 0;
    require(std::ifstream(path).good(), "path",
            [&] { return "cannot read '" + path + "'" + (errno != 0 ? std::string(": ") + std::strerror(errno) : ""); });
}

// A solid of a file with the name the file gives it.
struct NamedShape {
    TopoDS_Shape shape;
    std::string name;
};

// What a reader hands back: the file's shapes, and those of their solids (numbered in the order TopExp_Explorer
// meets them in the shapes in turn) that do not hold against themselves, where the caller asked to read a file
// of several solids without them (Faults).
struct FileShapes {
    std::vector<NamedShape> shapes;
    std::vector<SolidLeftOut> faulty;
};

// What a solid that does not hold against itself costs: the whole file (read_step, and read_step_all when no one
// is told what it leaves out), or only that solid when the file has others that hold.
enum class Faults { refuse_the_file, leave_the_solid_out };

// Conversion errors blamed on the file: "path: 'a.step': face 7: ...".
template <class Convert>
auto blamed_on(const std::string& path, Convert&& convert) {
    try {
        return convert();
    } catch (const Error& e) {
        throw Error("path", "'" + path + "': " + std::string(e.reason()));
    }
}

// The second half of the progress: the conversion of the shapes read.
Progress second_half(const Progress& progress) {
    return [&progress](double fraction) {
        if (progress) progress(0.5 + 0.5 * fraction);
    };
}

// The shape without the given solids: the compounds around them rebuilt (of their other parts, placed).
TopoDS_Shape without_solids(const TopoDS_Shape& shape, const TopTools_MapOfShape& dropped) {
    if (dropped.Contains(shape)) return {};
    if (shape.ShapeType() != TopAbs_COMPOUND && shape.ShapeType() != TopAbs_COMPSOLID) return shape;
    TopoDS_Compound rest;
    BRep_Builder builder;
    builder.MakeCompound(rest);
    for (TopoDS_Iterator it(shape); it.More(); it.Next())
        if (const TopoDS_Shape part = without_solids(it.Value(), dropped); !part.IsNull()) builder.Add(rest, part);
    return rest;
}

// The solids of the file's shapes, in order, each named; conversion errors blamed on the file. With `left_out`
// given, a solid the reader found faulty or that does not convert is left out when others are read, and
// `left_out` says which and why, by its place among the file's solids and its name.
std::vector<Solid> solids_from_file(const FileShapes& file, const std::string& path, const Progress& progress,
                                    std::string* left_out) {
    TopTools_MapOfShape faulty;
    std::vector<std::size_t> kept;  // the file's number of each solid handed to from_occt_all
    std::vector<std::string> names;  // the file's name of each solid, by the file's number
    std::size_t k = 0;
    auto fault = file.faulty.begin();
    for (const NamedShape& s : file.shapes)
        for (TopExp_Explorer it(s.shape, TopAbs_SOLID); it.More(); it.Next(), ++k) {
            names.push_back(s.name);
            if (fault != file.faulty.end() && fault->index == k) {
                faulty.Add(it.Current());
                ++fault;
            } else {
                kept.push_back(k);
            }
        }
    TopoDS_Compound all;
    BRep_Builder builder;
    builder.MakeCompound(all);
    for (const NamedShape& s : file.shapes)
        if (const TopoDS_Shape rest = without_solids(s.shape, faulty); !rest.IsNull()) builder.Add(all, rest);
    std::vector<SolidLeftOut> not_converted;
    std::string faces_left_out;
    std::vector<Solid> solids;
    try {
        solids = blamed_on(path, [&] {
            return from_occt_all(all, second_half(progress), left_out != nullptr ? &faces_left_out : nullptr,
                                 left_out != nullptr ? &not_converted : nullptr);
        });
    } catch (const Error&) {
        // No solid converts: the first the reader found faulty refuses the file, as it would without `left_out`.
        if (file.faulty.empty()) throw;
        const SolidLeftOut& first = file.faulty.front();
        throw Error("path", "'" + path + "': solid " + std::to_string(first.index) + ": " + first.reason);
    }
    if (names.empty()) {  // a file of faces, sewn into solids: numbered as sewn, named by none
        names.assign(solids.size() + not_converted.size(), "");
        kept.resize(names.size());
        std::iota(kept.begin(), kept.end(), std::size_t{0});
    }
    // from_occt_all meets the solids in the compound's order.
    std::vector<SolidLeftOut> solids_left_out = file.faulty;
    auto refused = not_converted.begin();
    for (std::size_t j = 0, out = 0; j < kept.size() && out < solids.size(); ++j) {
        if (refused != not_converted.end() && refused->index == j) {
            solids_left_out.push_back({kept[j], refused->reason});
            ++refused;
            continue;
        }
        solids[out++].set_name(names[kept[j]]);
    }
    if (left_out == nullptr) return solids;
    std::sort(solids_left_out.begin(), solids_left_out.end(),
              [](const SolidLeftOut& a, const SolidLeftOut& b) { return a.index < b.index; });
    std::string words;
    if (!solids_left_out.empty()) {
        words = "left out " + std::to_string(solids_left_out.size()) + " of " + std::to_string(names.size()) + " solids";
        for (std::size_t i = 0; i < solids_left_out.size(); ++i) {
            const SolidLeftOut& solid = solids_left_out[i];
            const std::string& name = names[solid.index];
            words += (i == 0 ? ": solid " : "; solid ") + std::to_string(solid.index) +
                     (name.empty() ? "" : " ('" + name + "')") + ": " + solid.reason;
        }
    }
    if (!faces_left_out.empty()) words += (words.empty() ? "" : "; ") + faces_left_out;
    *left_out = words;
    return solids;
}

// The file's one solid (exactly one, else the error says to read them all).
Solid one_solid(const FileShapes& file, const std::string& path, const Progress& progress, const char* all,
                std::string* left_out) {
    const std::vector<NamedShape>& shapes = file.shapes;
    std::size_t count = 0;
    for (const NamedShape& s : shapes)
        for (TopExp_Explorer it(s.shape, TopAbs_SOLID); it.More(); it.Next()) ++count;
    require(count <= 1, "path", "'" + path + "' holds " + std::to_string(count) + " solids; read them all with " + all);
    TopoDS_Compound compound;
    BRep_Builder builder;
    builder.MakeCompound(compound);
    for (const NamedShape& s : shapes) builder.Add(compound, s.shape);
    Solid solid = blamed_on(path, [&] { return from_occt(compound, second_half(progress), left_out); });
    for (const NamedShape& s : shapes)
        if (TopExp_Explorer(s.shape, TopAbs_SOLID).More()) solid.set_name(s.name);
    return solid;
}

// The name XCAF keeps on a label (a STEP product's name), or "" where there is none. OpenCASCADE's STEP writer
// names a product it was given no name for "Open CASCADE STEP translator <version> <n>" (FreeCAD's
// Part.export, our own unnamed solids): that is no name either.
std::string label_name(const TDF_Label& label) {
    Handle(TDataStd_Name) name;
    if (!label.FindAttribute(TDataStd_Name::GetID(), name)) return "";
    const TCollection_ExtendedString& text = name->Get();
    if (text.Search("Open CASCADE STEP translator ") == 1) return "";
    std::string out;
    for (int i = 1; i <= text.Length(); ++i) {
        const char16_t c = static_cast<char16_t>(text.Value(i));
        // UTF-8 of the Basic Multilingual Plane: a name is a label, not text to round-trip exactly.
        if (c < 0x80) {
            out += static_cast<char>(c);
        } else if (c < 0x800) {
            out += static_cast<char>(0xC0 | (c >> 6));
            out += static_cast<char>(0x80 | (c & 0x3F));
        } else {
            out += static_cast<char>(0xE0 | (c >> 12));
            out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
            out += static_cast<char>(0x80 | (c & 0x3F));
        }
    }
    return out;
}

// The leaves of an XCAF product structure, each placed where its instances put it: an assembly's components
// in order, a component by the product it refers to under the component's location (composed from the root).
void flatten(const Handle(XCAFDoc_ShapeTool)& tool, const TDF_Label& label, const TopLoc_Location& placement,
             std::vector<NamedShape>& out, int depth = 0) {
    // Product structures nest a few levels; a cycle (a hostile file) must not recurse without end.
    require(depth < 64, "path", "the file's assembly structure nests deeper than 64 levels (a cycle?)");
    if (tool->IsAssembly(label)) {
        TDF_LabelSequence components;
        tool->GetComponents(label, components);
        for (int i = 1; i <= components.Length(); ++i) {
            const TDF_Label component = components.Value(i);
            TDF_Label product;
            if (!tool->GetReferredShape(component, product)) continue;
            flatten(tool, product, placement * tool->GetLocation(component), out, depth + 1);
        }
        return;
    }
    const TopoDS_Shape shape = tool->GetShape(label);
    if (shape.IsNull()) return;
    out.push_back({placement.IsIdentity() ? shape : shape.Moved(placement), label_name(label)});
}

// The shapes as the file gives them, held against themselves (self_consistency.hpp), errors blamed on the file.
// Faults::leave_the_solid_out reads a file of several solids without those that do not hold, when others do.
FileShapes checked(std::vector<NamedShape> shapes, const std::string& path, Faults faults);

// Whether OpenCASCADE's STEP translation keeps the orientation the file gives each face's bounds or turns a bound
// it takes for the wrong way round (ShapeFix_Face::FixOrientation, FixOrientationMode in the FromSTEP sequence of
// its STEP resource). Its test is the sign of the area the bound's p-curves enclose (ShapeAnalysis::IsOuterBound),
// which cannot tell the two sides of a loop on a closed surface apart when a p-curve runs along the seam: FreeCAD's
// sphere minus a box at its centre, written by FreeCAD anywhere off the plane y = 0, was read as the eighth of the
// sphere inside the box (the box's faces turned to match), by FreeCAD and OpenCASCADE alike. The file's own
// orientation is read first; OpenCASCADE's turning is kept for files whose bounds need it (a face given by a seam
// alone, as a whole torus; read_step_shapes_here).
enum class FaceBounds { as_written, as_turned_by_occt };

// A ShapeFix_Shape that keeps each face's bounds as they come (FixOrientationMode 0), its other fixes OpenCASCADE's.
class ToolsKeepingFaceBounds : public ShapeAlgo_ToolContainer {
public:
    Handle(ShapeFix_Shape) FixShape() const override {
        Handle(ShapeFix_Shape) fix = ShapeAlgo_ToolContainer::FixShape();
        fix->FixFaceTool()->FixOrientationMode() = 0;
        return fix;
    }
};

// Sets the face bound rule of OpenCASCADE's STEP translation for one translation and puts the old one back, where
// the translation takes it from (XSAlgo_AlgoContainer::ProcessShape): without a STEP resource file (none is set,
// in Debian's OpenCASCADE and in FreeCAD) the ShapeFix_Shape of the tool container; with one (CSF_STEPDefaults),
// the resource's FixOrientationMode. Both are per process: the readers run in a child process.
class FaceBoundRule {
public:
    explicit FaceBoundRule(FaceBounds bounds)
        : resource_(ShapeProcess_Context().LoadResourceManager(Interface_Static::CVal("read.step.resource.name"))),
          sequence_(Interface_Static::CVal("read.step.sequence")),
          key_(sequence_ + ".FixShape.FixOrientationMode"),
          tools_(ShapeAlgo::AlgoContainer()->ToolContainer()) {
        if (bounds == FaceBounds::as_turned_by_occt) return;
        if (resource_->Find((sequence_ + ".exec.op").c_str())) {
            if (resource_->Find(key_.c_str())) old_mode_ = resource_->Integer(key_.c_str());
            resource_->SetResource(key_.c_str(), 0);
            set_mode_ = true;
        } else {
            ShapeAlgo::AlgoContainer()->SetToolContainer(new ToolsKeepingFaceBounds);
        }
    }
    ~FaceBoundRule() {
        ShapeAlgo::AlgoContainer()->SetToolContainer(tools_);
        if (set_mode_) resource_->SetResource(key_.c_str(), old_mode_);
    }
    FaceBoundRule(const FaceBoundRule&) = delete;
    FaceBoundRule& operator=(const FaceBoundRule&) = delete;

private:
    Handle(Resource_Manager) resource_;
    std::string sequence_, key_;
    Handle(ShapeAlgo_ToolContainer) tools_;
    bool set_mode_ = false;
    int old_mode_ = -1;  // OpenCASCADE's default: the fix on
};

// The shapes of a STEP file with their product names: XCAF's free shapes, assemblies flattened; each face's
// bounds kept as written or as OpenCASCADE turns them (FaceBounds).
std::vector<NamedShape> translated_step(const std::string& path, const Progress& progress, FaceBounds bounds) {
    try {
        // The parse is the first quarter of the progress, the translation the second (the conversion the second half).
        CapturedProgress captured(progress);
        STEPCAFControl_Reader reader;
        reader.SetNameMode(true);
        PolledFileBuffer buffer(path, captured, 0.25);
        std::istream stream(&buffer);
        const IFSelect_ReturnStatus parsed = reader.ChangeReader().ReadStream(path.c_str(), stream);
        captured.rethrow_if_stopped();
        require(parsed == IFSelect_RetDone, "path", "'" + path + "' is not a readable STEP file");
        const Handle(XCAFApp_Application) application = XCAFApp_Application::GetApplication();
        Handle(TDocStd_Document) document;
        application->NewDocument("MDTV-XCAF", document);
        Handle(PolledIndicator) indicator = new PolledIndicator(captured, 0.25, 0.5);
        bool transferred = false;
        {
            const FaceBoundRule rule(bounds);
            transferred = reader.Transfer(document, indicator->Start());
        }
        captured.rethrow_if_stopped();
        require(transferred, "path", "'" + path + "' holds no shape OpenCASCADE can translate");
        const Handle(XCAFDoc_ShapeTool) tool = XCAFDoc_DocumentTool::ShapeTool(document->Main());
        TDF_LabelSequence roots;
        tool->GetFreeShapes(roots);
        std::vector<NamedShape> shapes;
        for (int i = 1; i <= roots.Length(); ++i) flatten(tool, roots.Value(i), TopLoc_Location(), shapes);
        application->Close(document);
        require(!shapes.empty(), "path", "'" + path + "' holds no shape OpenCASCADE can translate");
        return shapes;
    } catch (const Standard_OutOfMemory&) {
        throw std::bad_alloc();
    } catch (const Standard_Failure& failure) {
        throw Error("path", "reading STEP from '" + path + "' failed: " + failure.GetMessageString());
    }
}

// The shapes of a STEP file, checked: with the face bounds as written where those make consistent solids, else as
// OpenCASCADE turns them (FaceBounds; its errors are the ones reported). Runs in the reader's child process
// (isolated_shapes).
FileShapes read_step_shapes_here(const std::string& path, const Progress& progress, Faults faults) {
    QuietMessenger quiet(QuietMessenger::Lock::skip_in_child);
    std::vector<NamedShape> written = translated_step(path, progress, FaceBounds::as_written);
    std::optional<FileShapes> as_written;
    try {
        as_written = checked(std::move(written), path, faults);
        if (as_written->faulty.empty()) return *std::move(as_written);
    } catch (const Error&) {
        // The file's bounds make no consistent solid as written.
    }
    // Translated again, OpenCASCADE turning the bounds; of the two readings, the one that leaves fewer solids
    // out (the file's own on a tie).
    try {
        FileShapes turned = checked(translated_step(path, progress, FaceBounds::as_turned_by_occt), path, faults);
        if (as_written && as_written->faulty.size() <= turned.faulty.size()) return *std::move(as_written);
        return turned;
    } catch (const Error&) {
        if (as_written) return *std::move(as_written);
        throw;
    }
}

// The shape of a .brep file (one, possibly a compound of several solids).
// Runs in the reader's child process (isolated_shapes).
FileShapes read_brep_shapes_here(const std::string& path, const Progress& progress, Faults faults) {
    QuietMessenger quiet(QuietMessenger::Lock::skip_in_child);
    {
        // BRepTools::Read prints to stdout when a file is not .brep: look at its first non-blank line first. A
        // .brep file starts with OCCT's "CASCADE Topology V<n>" or with BRepTools::Write's Draw tag line before it.
        std::ifstream in(path);
        std::string first;
        while (std::getline(in, first) && first.find_first_not_of(" \t\r") == std::string::npos) {
        }
        first.erase(0, first.find_first_not_of(" \t"));
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
    } catch (const Standard_OutOfMemory&) {
        throw std::bad_alloc();
    } catch (const Standard_Failure& failure) {
        throw Error("path", "reading .brep from '" + path + "' failed: " + failure.GetMessageString());
    }
    return checked({NamedShape{shape, ""}}, path, faults);
}

// The shapes as one compound, in order.
TopoDS_Compound compound_of(const std::vector<NamedShape>& shapes) {
    TopoDS_Compound all;
    BRep_Builder builder;
    builder.MakeCompound(all);
    for (const NamedShape& s : shapes) builder.Add(all, s.shape);
    return all;
}

FileShapes checked(std::vector<NamedShape> shapes, const std::string& path, Faults faults) {
    try {
        // Held against itself where OpenCASCADE's checks on a hostile shape cannot hurt the caller.
        const TopoDS_Compound all = compound_of(shapes);
        std::size_t solids = 0;
        for (TopExp_Explorer it(all, TopAbs_SOLID); it.More(); it.Next()) ++solids;
        if (faults == Faults::leave_the_solid_out && solids > 1) {
            // Each solid checked on its own, once: those that do not hold are left out while others do.
            std::vector<SolidLeftOut> faulty = detail::solid_faults(all);
            if (faulty.size() < solids) return {std::move(shapes), std::move(faulty)};
            const SolidLeftOut& first = faulty.front();
            throw Error("path", "'" + path + "': solid " + std::to_string(first.index) + ": " + first.reason);
        }
        blamed_on(path, [&] { detail::check_self_consistency(all); });
        return {std::move(shapes), {}};
    } catch (const Standard_OutOfMemory&) {
        throw std::bad_alloc();
    } catch (const Standard_Failure& failure) {
        throw Error("path", "reading '" + path + "' failed: " + failure.GetMessageString());
    }
}

// The child's answer: the names, the faulty solids, then the shapes as one compound in OpenCASCADE's binary
// format (exact doubles, unlike the .brep text's 15 digits).
std::string pack(const FileShapes& file) {
    std::ostringstream out(std::ios::binary);
    out << file.shapes.size() << '\n';
    for (const NamedShape& s : file.shapes) out << s.name.size() << '\n' << s.name;
    out << file.faulty.size() << '\n';
    for (const SolidLeftOut& f : file.faulty) out << f.index << '\n' << f.reason.size() << '\n' << f.reason;
    const TopoDS_Compound all = compound_of(file.shapes);
    BinTools::Write(all, out, /*theWithTriangles=*/false, /*theWithNormals=*/false, BinTools_FormatVersion_CURRENT);
    return out.str();
}

// pack's inverse, in the parent: the bytes come from our own child, not from the file.
FileShapes unpack(const std::string& bytes, const std::string& path) {
    std::istringstream in(bytes, std::ios::binary);
    const auto text = [&in] {
        std::size_t size = 0;
        in >> size;
        in.get();
        std::string out(size, '\0');
        in.read(out.data(), static_cast<std::streamsize>(size));
        return out;
    };
    std::size_t count = 0;
    in >> count;
    in.get();
    FileShapes file{std::vector<NamedShape>(count), {}};
    std::vector<NamedShape>& shapes = file.shapes;
    for (NamedShape& s : shapes) s.name = text();
    std::size_t faults = 0;
    in >> faults;
    in.get();
    file.faulty.resize(faults);
    for (SolidLeftOut& f : file.faulty) {
        in >> f.index;
        in.get();
        f.reason = text();
    }
    TopoDS_Shape all;
    try {
        BinTools::Read(all, in);
    } catch (const Standard_Failure& failure) {
        throw Error("path", "'" + path + "': the reader's answer is damaged: " + failure.GetMessageString());
    }
    require(!all.IsNull(), "path", "'" + path + "': the reader's answer is damaged");
    std::size_t k = 0;
    for (TopoDS_Iterator it(all); it.More() && k < count; it.Next()) shapes[k++].shape = it.Value();
    require(k == count, "path", "'" + path + "': the reader's answer is damaged");
    return file;
}

// The shapes `read_here` reads from the file and holds against themselves (checked), read in a child process
// under the reader's limits (child_process.hpp): OpenCASCADE crashing, looping or allocating without bound on a
// hostile file ends the child, not the caller, and the caller's Progress (Ctrl-C) kills it within a poll
// interval. The reading is the first half of the progress.
// `prescan` looks at the file's text first (file_prescan.hpp), in the parent: its refusals name the count.
FileShapes isolated_shapes(const std::string& path, const Progress& progress, Faults faults,
                           FileShapes (*read_here)(const std::string&, const Progress&, Faults),
                           void (*prescan)(const std::string&, const std::string&)) {
    require_readable(path);
    std::error_code error;
    const auto size = static_cast<std::size_t>(std::filesystem::file_size(path, error));
    {
        std::ifstream in(path, std::ios::binary);
        std::ostringstream text;
        text << in.rdbuf();
        prescan(path, text.str());
    }
    const Progress first_half = progress_part(progress, 0, 0.5);
    const std::string packed = detail::run_in_child(
        "'" + path + "'", detail::reader_limits(error ? 0 : size), first_half, [&](const detail::ChildProgress& report) {
            // The child reports the whole read as [0, 1] of its part; the readers report [0, 0.5] of theirs.
            const Progress child_progress = [&report](double fraction) { report(2 * fraction); };
            try {
                return pack(read_here(path, child_progress, faults));  // checked by the reader
            } catch (const Standard_OutOfMemory&) {
                throw std::bad_alloc();
            } catch (const Standard_Failure& failure) {
                throw Error("path", "reading '" + path + "' failed: " + failure.GetMessageString());
            }
        });
    return unpack(packed, path);
}

FileShapes read_step_shapes(const std::string& path, const Progress& progress, Faults faults = Faults::refuse_the_file) {
    return isolated_shapes(path, progress, faults, read_step_shapes_here, detail::prescan_step);
}

FileShapes read_brep_shapes(const std::string& path, const Progress& progress, Faults faults = Faults::refuse_the_file) {
    return isolated_shapes(path, progress, faults, read_brep_shapes_here, detail::prescan_brep);
}

}  // namespace

// Both writers go through output_file.hpp: the path is checked and a temporary file made first (cheap
// checks before the conversion), OpenCASCADE writes that file by name, and it is renamed over the target.
// STEP goes through XCAF so that each solid is a product named after Solid::name, which read_step_all gives back.
void write_step(std::span<const Solid> solids, const std::string& path, const ConvertOptions& options) {
    require(!solids.empty(), "solids", "is empty");
    output::write_file_by_name(path, [&](const std::string& name) {
        std::vector<TopoDS_Solid> shapes;
        shapes.reserve(solids.size());
        for (const Solid& solid : solids) shapes.push_back(to_occt(solid, options));
        QuietMessenger quiet;
        try {
            Handle(TDocStd_Document) document;
            XCAFApp_Application::GetApplication()->NewDocument("MDTV-XCAF", document);
            const Handle(XCAFDoc_ShapeTool) tool = XCAFDoc_DocumentTool::ShapeTool(document->Main());
            for (std::size_t i = 0; i < solids.size(); ++i) {
                const TDF_Label label = tool->AddShape(shapes[i], /*makeAssembly=*/false);
                // XCAF names a new label after its shape type ("SOLID"); an unnamed solid stays unnamed.
                if (solids[i].name().empty())
                    label.ForgetAttribute(TDataStd_Name::GetID());
                else
                    TDataStd_Name::Set(label, TCollection_ExtendedString(solids[i].name().c_str(), /*isMultiByte=*/true));
            }
            STEPCAFControl_Writer writer;  // its constructor initialises the STEP statics (STEPControl_Controller::Init)
            Interface_Static::SetCVal("write.step.schema", "AP214IS");
            // The file's uncertainty is the greatest tolerance of the solids, not OpenCASCADE's default average: a
            // reader takes it as its precision and refits every p-curve further from its edge than that. Read
            // solids carry their edges' measured tolerances (topology.cpp), and with their average as the
            // uncertainty a hotend mount read from an Autodesk STEP file came back through our own STEP 3.7e-7 off
            // in volume (1.3e-11 so). Per process, and put back at once (FreeCAD writes its own STEP files in the
            // same session).
            const int precision_mode = Interface_Static::IVal("write.precision.mode");
            Interface_Static::SetIVal("write.precision.mode", 1);
            const bool transferred = writer.Transfer(document, STEPControl_AsIs);
            Interface_Static::SetIVal("write.precision.mode", precision_mode);
            require(transferred, "solids", "OpenCASCADE could not translate them to STEP");
            require(writer.Write(name.c_str()) == IFSelect_RetDone, "path", "cannot write '" + path + "'");
            XCAFApp_Application::GetApplication()->Close(document);
        } catch (const Standard_Failure& failure) {
            throw Error("path", "writing STEP to '" + path + "' failed: " + failure.GetMessageString());
        }
    });
}

void write_step(const Solid& solid, const std::string& path, const ConvertOptions& options) {
    write_step(std::span(&solid, 1), path, options);
}

void write_brep(std::span<const Solid> solids, const std::string& path, const ConvertOptions& options) {
    require(!solids.empty(), "solids", "is empty");
    output::write_file_by_name(path, [&](const std::string& name) {
        // One solid is written bare, as OpenCASCADE and FreeCAD write a solid (the text brep_string gives).
        TopoDS_Shape shape;
        if (solids.size() == 1) {
            shape = to_occt(solids.front(), options);
        } else {
            TopoDS_Compound compound;
            BRep_Builder builder;
            builder.MakeCompound(compound);
            for (const Solid& solid : solids) builder.Add(compound, to_occt(solid, options));
            shape = compound;
        }
        require(BRepTools::Write(shape, name.c_str()), "path", "cannot write '" + path + "'");
    });
}

void write_brep(const Solid& solid, const std::string& path, const ConvertOptions& options) {
    write_brep(std::span(&solid, 1), path, options);
}

std::string brep_string(const Solid& solid, const ConvertOptions& options) {
    std::ostringstream out;
    // BRepTools::Write(shape, file) starts the file with this line (the Draw shape tag) and the stream
    // version does not; write it so the string is exactly the file's text. Both readers accept either.
    out << "DBRep_DrawableShape\n";
    BRepTools::Write(to_occt(solid, options), out);
    return out.str();
}

namespace {

// Every solid of a model file named, and no two alike, so that a name picks one solid (a dict's key, a module, a
// report): the file's name for it where it gives one, else the file's stem (stem_k among several); a repeated
// name (instances of one part in an assembly share their product's) numbered _2, _3, ...
std::vector<Solid> named_after_file(std::vector<Solid> solids, const std::string& path) {
    const std::string stem = std::filesystem::path(path).stem().string();
    std::map<std::string, int> seen;
    for (std::size_t i = 0; i < solids.size(); ++i) {
        // Appended piece by piece: gcc 12 takes "_" + std::to_string(k) for an overlapping copy (-Wrestrict).
        std::string name = solids[i].name();
        if (name.empty()) {
            name = stem;
            if (solids.size() > 1) name.append("_").append(std::to_string(i + 1));
        }
        if (const int count = ++seen[name]; count > 1) name.append("_").append(std::to_string(count));
        solids[i].set_name(name);
    }
    return solids;
}

}  // namespace

Solid read_step(const std::string& path, const Progress& progress, std::string* left_out) {
    Solid solid = one_solid(read_step_shapes(path, progress), path, progress, "read_step_all", left_out);
    return named_after_file({std::move(solid)}, path).front();
}

Solid read_brep(const std::string& path, const Progress& progress, std::string* left_out) {
    Solid solid = one_solid(read_brep_shapes(path, progress), path, progress, "read_brep_all", left_out);
    return named_after_file({std::move(solid)}, path).front();
}

namespace {

// A faulty solid among others is left out only where the caller hears of it.
Faults faults_for(const std::string* left_out) {
    return left_out != nullptr ? Faults::leave_the_solid_out : Faults::refuse_the_file;
}

}  // namespace

std::vector<Solid> read_step_all(const std::string& path, const Progress& progress, std::string* left_out) {
    return named_after_file(solids_from_file(read_step_shapes(path, progress, faults_for(left_out)), path, progress, left_out), path);
}

std::vector<Solid> read_brep_all(const std::string& path, const Progress& progress, std::string* left_out) {
    return named_after_file(solids_from_file(read_brep_shapes(path, progress, faults_for(left_out)), path, progress, left_out), path);
}

}  // namespace ratbez::occt
