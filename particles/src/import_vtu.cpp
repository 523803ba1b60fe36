// .vtu import: the only translation unit that sees VTK headers.
//
// VTK 9.1's XML reader trusts the sizes a file gives (attributes, cell offsets,
// compression headers) and allocates, loops or divides by them before checking
// anything. The importer therefore reads in three steps: the XML is parsed
// (UpdateInformation) and every size VTK will act on is checked against the file,
// then VTK reads the data, then everything read is checked before it is used: the
// grid's cell array (offsets, sizes, types and point ids) and the coordinates.
// VTK's own diagnostics are collected meanwhile and folded into the one
// CloudError, so a bad file gives a single message naming it and nothing else on
// the terminal.
#include "rkpm/particles/element_geometry.hpp"
#include "rkpm/particles/generators.hpp"

#include <vtkCallbackCommand.h>
#include <vtkCellArray.h>
#include <vtkCellTypes.h>
#include <vtkCommand.h>
#include <vtkLogger.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkOutputWindow.h>
#include <vtkPoints.h>
#include <vtkSetGet.h>
#include <vtkSmartPointer.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <locale>
#include <map>
#include <new>
#include <optional>
#include <sstream>
#include <system_error>
#include <vector>

namespace rkpm::particles {
namespace {

[[noreturn]] void fail(const std::string& path, const std::string& what) {
  throw CloudError("import_vtu '" + path + "': " + what);
}

// An output window that keeps what VTK would print (errors of the reader and of
// the pipeline executive, warnings of the XML parser) instead of printing it.
class CollectingOutputWindow : public vtkOutputWindow {
 public:
  static CollectingOutputWindow* New();
  vtkTypeMacro(CollectingOutputWindow, vtkOutputWindow)
  void DisplayText(const char* text) override {
    if (text) (this->GetCurrentMessageType() == MESSAGE_TYPE_ERROR ? errors : others) += text;
  }
  std::string errors;  // a file with errors is refused
  std::string others;  // warnings and text: dropped when the file reads

 protected:
  CollectingOutputWindow() = default;
  ~CollectingOutputWindow() override = default;
};
vtkStandardNewMacro(CollectingOutputWindow);

// For its lifetime, VTK's messages go to a CollectingOutputWindow and vtkLogger
// writes nothing to stderr (VTK 9 logs each error there as well as to the output
// window). Both are restored afterwards.
class CaptureVtkMessages {
 public:
  CaptureVtkMessages()
      : previous_window_(vtkOutputWindow::GetInstance()), previous_verbosity_(vtkLogger::GetCurrentVerbosityCutoff()) {
    vtkOutputWindow::SetInstance(window_);
    vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  }
  ~CaptureVtkMessages() {
    vtkOutputWindow::SetInstance(previous_window_);
    vtkLogger::SetStderrVerbosity(previous_verbosity_);
  }
  CaptureVtkMessages(const CaptureVtkMessages&) = delete;
  CaptureVtkMessages& operator=(const CaptureVtkMessages&) = delete;

  std::string& errors() { return window_->errors; }

 private:
  vtkSmartPointer<vtkOutputWindow> previous_window_;
  vtkLogger::Verbosity previous_verbosity_;
  vtkNew<CollectingOutputWindow> window_;
};

// Errors the reader reports through its own ErrorEvent (it then prints nothing),
// in order with those of the XML parser and the pipeline.
void collect_error(vtkObject*, unsigned long, void* client_data, void* call_data) {
  auto* messages = static_cast<std::string*>(client_data);
  if (call_data) *messages += static_cast<const char*>(call_data);
}

// The first line of VTK's messages that says what is wrong: terminal escape
// sequences removed, the "ERROR: In FILE, line N" headers and the
// "vtkClass (0x...): " prefix dropped.
std::string first_meaningful_line(const std::string& messages) {
  std::string clean;
  for (std::size_t i = 0; i < messages.size(); ++i) {
    const char c = messages[i];
    if (c == '\x1b') {  // CSI sequence: ESC [ parameters final-byte
      if (i + 1 < messages.size() && messages[i + 1] == '[') {
        i += 2;
        while (i < messages.size() && !(messages[i] >= '@' && messages[i] <= '~')) ++i;
      }
      continue;
    }
    if (c == '\n' || (static_cast<unsigned char>(c) >= 0x20 && c != '\x7f')) clean += c;
  }
  std::istringstream lines(clean);
  std::string line;
  while (std::getline(lines, line)) {
    const auto begin = line.find_first_not_of(" \t");
    if (begin == std::string::npos) continue;
    line.erase(0, begin);
    if (line.rfind("ERROR: In ", 0) == 0 || line.rfind("Warning: In ", 0) == 0 ||
        line.rfind("Generic Warning: In ", 0) == 0) {
      continue;
    }
    const auto prefix = line.find("): ");
    if (line.rfind("vtk", 0) == 0 && prefix != std::string::npos && line.find(" (", 0) < prefix) {
      line.erase(0, prefix + 3);
    }
    constexpr std::size_t max_length = 300;
    if (line.size() > max_length) line = line.substr(0, max_length) + "...";
    return line;
  }
  return "";
}

// The sizes a file declares, checked before VTK's reader acts on them: it
// allocates and loops by them without bounds (NumberOfComponents = "34294967295"
// overflows int and makes VTK 9.1 loop over that many component names, a hang; a last
// cell offset of 2^61 makes it allocate a wrapped-around size and write past it;
// docs/verification/fuzzing.md lists what the fuzzers found). VTK reads attributes
// with operator>>; a value that does not parse that way as an integer, or lies outside
// its range, is refused.
//   NumberOfComponents of an array: 1 to kMaxComponents
//   the offset of an array's appended data: 0 to the file's size
//   the points and the cells of all pieces, and the values of all arrays
//     (tuples x components): at most kItemsPerFileByte per byte of the file;
//     even compressed, a real mesh takes well over a byte per 64 values (its
//     coordinates and connectivity hardly compress)
//   the cell offsets: at most 8 points per cell (tetrahedra and hexahedra only)
constexpr long long kMaxComponents = 1024;
constexpr long long kItemsPerFileByte = 64;
constexpr long long kMaxPointsPerCell = 8;

std::string element_label(vtkXMLDataElement* element) {
  std::string label = element->GetName() ? element->GetName() : "element";
  if (const char* name = element->GetAttribute("Name")) label += std::string(" \"") + name + "\"";
  return label;
}

// The attribute's value, `absent` if the element does not have it.
long long integer_attribute(const std::string& path, vtkXMLDataElement* element, const char* attribute,
                            long long min, long long max, long long absent) {
  const char* text = element->GetAttribute(attribute);
  if (text == nullptr) return absent;
  std::istringstream in(text);
  long long value = 0;
  in >> value;
  if (!in.fail() && value >= min && value <= max) return value;
  std::string shown = text;
  if (shown.size() > 40) shown = shown.substr(0, 40) + "...";
  fail(path, element_label(element) + " declares " + attribute + "=\"" + shown + "\", expected an integer from " +
                 std::to_string(min) + " to " + std::to_string(max));
}

long long max_items_for(const std::string& path) {
  std::error_code ec;
  const auto file_size = std::filesystem::file_size(path, ec);
  const std::uintmax_t bytes = ec ? 1 : std::max<std::uintmax_t>(file_size, 1);
  return static_cast<long long>(std::min<std::uintmax_t>(bytes, std::numeric_limits<std::int32_t>::max()) *
                                kItemsPerFileByte);
}

// Walks the parsed XML (no array has been read yet) and checks every declared size.
void check_declared_sizes(const std::string& path, vtkXMLDataElement* root, long long max_items) {
  struct Pending {
    vtkXMLDataElement* element;
    long long tuples;  // tuples of the arrays inside (points or cells of the piece), -1 if not known
  };
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);
  const long long file_bytes =
      ec ? 0 : static_cast<long long>(std::min<std::uintmax_t>(size, std::numeric_limits<long long>::max()));
  std::vector<Pending> pending = {{root, -1}};
  long long total_points = 0, total_cells = 0, total_values = 0;
  const auto too_many = [&](const std::string& what, long long count) {
    fail(path, "the file declares " + std::to_string(count) + " " + what + " in all, more than it can hold (" +
                   std::to_string(max_items) + " at most for its size)");
  };
  while (!pending.empty()) {
    const Pending item = pending.back();
    pending.pop_back();
    vtkXMLDataElement* element = item.element;
    if (element == nullptr) continue;
    const std::string name = element->GetName() ? element->GetName() : "";
    long long n_points = -1, n_cells = -1;
    if (name == "Piece") {
      n_points = integer_attribute(path, element, "NumberOfPoints", 0, max_items, -1);
      n_cells = integer_attribute(path, element, "NumberOfCells", 0, max_items, -1);
      if ((total_points += std::max(n_points, 0LL)) > max_items) too_many("points", total_points);
      if ((total_cells += std::max(n_cells, 0LL)) > max_items) too_many("cells", total_cells);
    } else if (name == "DataArray" || name == "Array") {
      // Appended data start at most at the end of the file.
      integer_attribute(path, element, "offset", 0, file_bytes, 0);
      const long long components = integer_attribute(path, element, "NumberOfComponents", 1, kMaxComponents, 1);
      const long long declared = integer_attribute(path, element, "NumberOfTuples", 0, max_items, -1);
      const long long tuples = declared >= 0 ? declared : item.tuples;
      if (tuples >= 0 && components * tuples > max_items) {
        fail(path, element_label(element) + " declares " + std::to_string(tuples) + " tuples of " +
                       std::to_string(components) + " components, more than the file can hold (" +
                       std::to_string(max_items) + " values at most)");
      }
      if (tuples >= 0 && (total_values += components * tuples) > max_items) too_many("array values", total_values);
    } else if (name == "InformationKey") {
      integer_attribute(path, element, "length", 0, kMaxComponents, 0);
    }
    for (int i = 0; i < element->GetNumberOfNestedElements(); ++i) {
      vtkXMLDataElement* child = element->GetNestedElement(i);
      const std::string child_name = child && child->GetName() ? child->GetName() : "";
      long long tuples = item.tuples;
      if (name == "Piece") tuples = (child_name == "Points" || child_name == "PointData") ? n_points
                                    : child_name == "CellData"                          ? n_cells
                                                                                        : -1;
      pending.push_back({child, tuples});
    }
  }
}

bool is_integer_type(int type) {
  switch (type) {
    case VTK_CHAR: case VTK_SIGNED_CHAR: case VTK_UNSIGNED_CHAR: case VTK_SHORT: case VTK_UNSIGNED_SHORT:
    case VTK_INT: case VTK_UNSIGNED_INT: case VTK_LONG: case VTK_UNSIGNED_LONG: case VTK_LONG_LONG:
    case VTK_UNSIGNED_LONG_LONG: case VTK_ID_TYPE:
      return true;
    default:
      return false;
  }
}

// The largest of the first `count` words in `bytes`; nothing if there is none.
template <typename T>
std::optional<long double> largest_word(const std::vector<unsigned char>& bytes, std::size_t count) {
  std::optional<long double> largest;
  for (std::size_t i = 0; i < count; ++i) {
    T value;
    std::memcpy(&value, bytes.data() + i * sizeof(T), sizeof(T));
    const auto v = static_cast<long double>(value);
    if (!largest || v > *largest) largest = v;
  }
  return largest;
}

// Up to `n` bytes of base64 data, decoded the way VTK's reader decodes them
// (vtkBase64InputStream): groups of four characters; '=' is a zero digit except
// as the group's third or fourth character, where it ends the data after one or
// two bytes; any other character outside the alphabet ends the data before its
// group. The header checks below must see exactly the bytes VTK will use.
std::string decode_base64_like_vtk(std::istream& in, std::size_t n) {
  const auto digit = [](char c) -> int {
    if (c >= 'A' && c <= 'Z') return c - 'A';
    if (c >= 'a' && c <= 'z') return c - 'a' + 26;
    if (c >= '0' && c <= '9') return c - '0' + 52;
    if (c == '+') return 62;
    if (c == '/') return 63;
    if (c == '=') return 0;
    return -1;
  };
  std::string bytes;
  char group[4];
  while (bytes.size() < n && in.read(group, 4) && in.gcount() == 4) {
    int d[4];
    for (int k = 0; k < 4; ++k) d[k] = digit(group[k]);
    if (d[0] < 0 || d[1] < 0 || d[2] < 0 || d[3] < 0) break;
    const char decoded[3] = {static_cast<char>((d[0] << 2) | (d[1] >> 4)),
                             static_cast<char>(((d[1] & 0xF) << 4) | (d[2] >> 2)),
                             static_cast<char>(((d[2] & 0x3) << 6) | d[3])};
    const std::size_t count = group[2] == '=' ? 1 : group[3] == '=' ? 2 : 3;
    bytes.append(decoded, count);
    if (count < 3) break;
  }
  if (bytes.size() > n) bytes.resize(n);
  return bytes;
}

// Where VTK's reader takes an array's data from (vtkXMLDataReader's
// ReadArrayValues): the appended data when the element has an offset attribute,
// whatever its format says (an unparsable offset counts as 0); otherwise inline,
// binary for format="binary" and ascii for anything else.
struct ArrayData {
  enum Kind { Ascii, Binary, Appended } kind;
  vtkTypeInt64 offset;
};

ArrayData where_vtk_reads(vtkXMLDataElement* array) {
  if (array->GetAttribute("offset") != nullptr) {
    vtkTypeInt64 offset = 0;
    array->GetScalarAttribute("offset", offset);
    return {ArrayData::Appended, offset};
  }
  const char* format = array->GetAttribute("format");
  return {format && std::string(format) == "binary" ? ArrayData::Binary : ArrayData::Ascii, 0};
}

// Compressed binary data start with a header: the number of blocks, the size of a
// block before compression, that of the last block (0 if it is full), then the
// compressed size of each block. VTK 9.1 trusts all of it: it allocates and
// zeroes the list of sizes by the block count (2^32 - 1 blocks in a 1.4 kB file:
// 16 GB), allocates each block by its sizes, divides by the block size (0: SIGFPE)
// and reads the list it did not allocate when the count is 0 but the last block
// is not (SIGSEGV). Each header is read here first and must describe data the
// file can hold.
void check_compression_headers(const std::string& path, vtkXMLDataParser* parser, std::istream& stream,
                               long long max_items) {
  vtkXMLDataElement* root = parser->GetRootElement();
  if (root->GetAttribute("compressor") == nullptr) return;
  const char* header_type = root->GetAttribute("header_type");
  const std::size_t word = header_type && std::string(header_type) == "UInt64" ? 8 : 4;
  const char* byte_order = root->GetAttribute("byte_order");
  const bool big_endian = byte_order && std::string(byte_order) == "BigEndian";
  std::error_code ec;
  const std::uintmax_t file_size = std::filesystem::file_size(path, ec);
  if (ec) return;
  // VTK's parser stops at the (first) AppendedData element and decodes its data
  // as base64 unless it says encoding="raw".
  bool appended_raw = false;
  if (vtkXMLDataElement* appended = root->LookupElementWithName("AppendedData")) {
    const char* encoding = appended->GetAttribute("encoding");
    appended_raw = encoding && std::string(encoding) == "raw";
  }

  std::vector<vtkXMLDataElement*> pending = {root};
  while (!pending.empty()) {
    vtkXMLDataElement* element = pending.back();
    pending.pop_back();
    for (int i = 0; i < element->GetNumberOfNestedElements(); ++i) pending.push_back(element->GetNestedElement(i));
    const std::string name = element->GetName() ? element->GetName() : "";
    if (name != "DataArray" && name != "Array") continue;
    const ArrayData data = where_vtk_reads(element);
    bool raw = false;
    stream.clear();
    if (data.kind == ArrayData::Binary) {
      // Inline data start after the opening tag and any whitespace.
      stream.seekg(element->GetXMLByteIndex());
      char c = 0;
      while (stream.get(c) && c != '>') {
      }
      while (stream.get(c) && (c == ' ' || c == '\t' || c == '\n' || c == '\r')) {
      }
      stream.unget();
    } else if (data.kind == ArrayData::Appended) {
      // check_declared_sizes has bounded the offset by the file's size.
      const vtkTypeInt64 at = parser->GetAppendedDataPosition() + data.offset;
      stream.seekg(at);
      raw = appended_raw;
    } else {
      continue;
    }
    const std::streampos start = stream.tellg();
    const auto read_words = [&](std::size_t count) {
      stream.clear();
      stream.seekg(start);
      std::string bytes(count * word, '\0');
      if (raw) {
        stream.read(bytes.data(), static_cast<std::streamsize>(bytes.size()));
        bytes.resize(static_cast<std::size_t>(std::max<std::streamsize>(stream.gcount(), 0)));
      } else {
        bytes = decode_base64_like_vtk(stream, count * word);
      }
      std::vector<std::uint64_t> words;
      for (std::size_t k = 0; (k + 1) * word <= bytes.size(); ++k) {
        std::uint64_t v = 0;
        for (std::size_t b = 0; b < word; ++b) {
          v = (v << 8) | static_cast<unsigned char>(bytes[k * word + (big_endian ? b : word - 1 - b)]);
        }
        words.push_back(v);
      }
      return words;
    };
    const auto refuse = [&](const std::string& what) {
      fail(path, element_label(element) + ": its compression header " + what);
    };
    const std::vector<std::uint64_t> header = read_words(3);
    if (header.size() < 3) continue;  // the reader reports a short header
    const std::uint64_t blocks = header[0], block_size = header[1], last_size = header[2];
    if (blocks > file_size / word) {
      refuse("declares " + std::to_string(blocks) + " blocks, more than the file can hold");
    }
    if (blocks == 0 && last_size != 0) {
      refuse("declares no block but a last block of " + std::to_string(last_size) + " bytes");
    }
    if (blocks > 0 && (block_size == 0 || last_size > block_size)) {
      refuse("declares blocks of " + std::to_string(block_size) + " bytes and a last block of " +
             std::to_string(last_size) + " bytes");
    }
    if (static_cast<long double>(blocks) * block_size > 8.0L * max_items) {
      refuse("declares " + std::to_string(blocks) + " blocks of " + std::to_string(block_size) +
             " bytes, more data than the file can hold");
    }
    const std::vector<std::uint64_t> sizes = read_words(3 + blocks);
    for (std::size_t b = 3; b < sizes.size(); ++b) {
      if (sizes[b] > file_size) {
        refuse("declares a compressed block of " + std::to_string(sizes[b]) + " bytes, more than the file holds");
      }
    }
  }
}

// The data VTK sizes its work by, read first with a parser of our own over the
// same file (the reader's parser keeps state between reads): every compression
// header, then each piece's cell offsets. VTK sizes the connectivity by the last
// offset before it checks anything; the largest must not exceed
// kMaxPointsPerCell per declared cell.
void check_data(const std::string& path, vtkXMLDataParser* reader_parser, long long max_items) {
  std::ifstream stream(path, std::ios::binary);
  stream.imbue(std::locale::classic());
  vtkNew<vtkXMLDataParser> parser;
  parser->SetStream(&stream);
  if (!parser->Parse() || parser->GetRootElement() == nullptr) return;  // the reader reports it
  parser->SetCompressor(reader_parser->GetCompressor());
  check_compression_headers(path, parser, stream, max_items);
  stream.clear();
  vtkXMLDataElement* grid = parser->GetRootElement()->FindNestedElementWithName("UnstructuredGrid");
  if (grid == nullptr) return;
  for (int p = 0; p < grid->GetNumberOfNestedElements(); ++p) {
    vtkXMLDataElement* piece = grid->GetNestedElement(p);
    if (piece == nullptr || piece->GetName() == nullptr || std::string(piece->GetName()) != "Piece") continue;
    long long n_cells = 0;
    vtkXMLDataElement* cells = piece->FindNestedElementWithName("Cells");
    if (cells == nullptr || !piece->GetScalarAttribute("NumberOfCells", n_cells) || n_cells <= 0) continue;
    vtkXMLDataElement* offsets = cells->FindNestedElementWithNameAndAttribute("DataArray", "Name", "offsets");
    int type = 0;
    if (offsets == nullptr || !offsets->GetWordTypeAttribute("type", type) || !is_integer_type(type)) continue;
    const std::size_t word_size = parser->GetWordTypeSize(type);
    const auto count = static_cast<std::size_t>(n_cells);
    std::vector<unsigned char> bytes(count * word_size);
    const ArrayData data = where_vtk_reads(offsets);
    const std::size_t read =
        data.kind == ArrayData::Appended
            ? parser->ReadAppendedData(data.offset, bytes.data(), 0, count, type)
            : parser->ReadInlineData(offsets, data.kind == ArrayData::Ascii, bytes.data(), 0, count, type);
    std::optional<long double> largest;
    switch (type) {
      vtkTemplateMacro(largest = largest_word<VTK_TT>(bytes, std::min(read, count)));
    }
    if (largest && *largest > static_cast<long double>(kMaxPointsPerCell) * static_cast<long double>(n_cells)) {
      std::ostringstream msg;
      msg << "the cell offsets of piece " << p << " reach " << std::setprecision(20) << *largest << " for "
          << n_cells << " cells, more than " << kMaxPointsPerCell
          << " points per cell (only VTK_TETRA and VTK_HEXAHEDRON are accepted)";
      fail(path, msg.str());
    }
  }
}

std::string cell_type_name(int type) {
  const char* name = vtkCellTypes::GetClassNameFromTypeId(type);
  return (name ? std::string(name) : std::string("unknown")) + " (VTK type " + std::to_string(type) + ")";
}

// The cell array as read: offsets (n_cells + 1, starting at 0, never decreasing,
// ending at the connectivity's length) and the point ids of every cell.
struct CellView {
  const vtkTypeInt64* offsets64 = nullptr;
  const vtkTypeInt32* offsets32 = nullptr;
  const vtkTypeInt64* ids64 = nullptr;
  const vtkTypeInt32* ids32 = nullptr;
  vtkIdType n_offsets = 0;
  vtkIdType n_ids = 0;

  std::int64_t offset(vtkIdType i) const { return offsets64 ? offsets64[i] : offsets32[i]; }
  std::int64_t id(std::int64_t k) const { return ids64 ? ids64[k] : ids32[k]; }
};

CellView view_cells(const std::string& path, vtkCellArray* cells) {
  CellView view;
  if (cells == nullptr) fail(path, "the grid has no cell array");
  vtkDataArray* offsets = cells->GetOffsetsArray();
  vtkDataArray* ids = cells->GetConnectivityArray();
  if (offsets == nullptr || ids == nullptr || offsets->GetNumberOfComponents() != 1 ||
      ids->GetNumberOfComponents() != 1) {
    fail(path, "the cell array has no offsets or connectivity");
  }
  view.n_offsets = offsets->GetNumberOfValues();
  view.n_ids = ids->GetNumberOfValues();
  if (cells->IsStorage64Bit()) {
    view.offsets64 = cells->GetOffsetsArray64()->GetPointer(0);
    view.ids64 = cells->GetConnectivityArray64()->GetPointer(0);
  } else {
    view.offsets32 = cells->GetOffsetsArray32()->GetPointer(0);
    view.ids32 = cells->GetConnectivityArray32()->GetPointer(0);
  }
  if (view.n_offsets < 1 || view.offset(0) != 0) fail(path, "the cell offsets do not start at 0");
  for (vtkIdType c = 0; c + 1 < view.n_offsets; ++c) {
    if (view.offset(c + 1) < view.offset(c)) {
      fail(path, "the cell offsets decrease at cell " + std::to_string(c) + " (" + std::to_string(view.offset(c)) +
                     " then " + std::to_string(view.offset(c + 1)) + ")");
    }
  }
  if (view.offset(view.n_offsets - 1) != view.n_ids) {
    fail(path, "the cell offsets end at " + std::to_string(view.offset(view.n_offsets - 1)) +
                   " but the connectivity has " + std::to_string(view.n_ids) + " point ids");
  }
  return view;
}

// Checks every cell of the grid before any of them is used: supported types, the
// number of points each type has, point ids inside [0, n_points).
void check_cells(const std::string& path, const CellView& cells, vtkUnsignedCharArray* types, vtkIdType n_points) {
  const vtkIdType n_cells = cells.n_offsets - 1;
  if (types == nullptr || types->GetNumberOfValues() != n_cells || types->GetNumberOfComponents() != 1) {
    fail(path, "the grid has " + std::to_string(n_cells) + " cells but " +
                   std::to_string(types ? types->GetNumberOfValues() : 0) + " cell types");
  }
  std::map<int, vtkIdType> unsupported;  // cell type -> count
  for (vtkIdType c = 0; c < n_cells; ++c) {
    const int type = types->GetValue(c);
    if (type != VTK_TETRA && type != VTK_HEXAHEDRON) ++unsupported[type];
  }
  if (!unsupported.empty()) {
    std::ostringstream msg;
    msg << "unsupported cell types (only VTK_TETRA and VTK_HEXAHEDRON are accepted):";
    for (const auto& [type, count] : unsupported) msg << " " << count << " x " << cell_type_name(type) << ";";
    fail(path, msg.str());
  }
  if (n_cells == 0) fail(path, "the grid has no cells");
  if (n_cells > std::numeric_limits<std::int32_t>::max() - 1) {
    fail(path, "the grid has " + std::to_string(n_cells) + " cells, more than a cloud can hold");
  }
  for (vtkIdType c = 0; c < n_cells; ++c) {
    const int type = types->GetValue(c);
    const std::int64_t begin = cells.offset(c), size = cells.offset(c + 1) - begin;
    const int expected = type == VTK_TETRA ? 4 : 8;
    if (size != expected) {
      fail(path, "cell " + std::to_string(c) + " (" + cell_type_name(type) + ") has " + std::to_string(size) +
                     " points, expected " + std::to_string(expected));
    }
    for (std::int64_t k = begin; k < begin + size; ++k) {
      const std::int64_t id = cells.id(k);
      if (id < 0 || id >= n_points) {
        fail(path, "cell " + std::to_string(c) + " (" + cell_type_name(type) + ") refers to point " +
                       std::to_string(id) + ", but the file has " + std::to_string(n_points) +
                       " points (ids 0 to " + std::to_string(n_points - 1) + ")");
      }
    }
  }
}

}  // namespace

Cloud import_vtu(const std::string& path) {
  if (!std::ifstream(path).good()) fail(path, "cannot open the file for reading");

  CaptureVtkMessages capture;
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  if (!reader->CanReadFile(path.c_str())) fail(path, "not a VTK XML UnstructuredGrid (.vtu) file");
  vtkNew<vtkCallbackCommand> on_error;
  on_error->SetCallback(collect_error);
  on_error->SetClientData(&capture.errors());
  reader->AddObserver(vtkCommand::ErrorEvent, on_error);
  reader->SetFileName(path.c_str());
  const auto refuse_on_errors = [&]() {
    if (capture.errors().empty()) return;
    std::string what = first_meaningful_line(capture.errors());
    fail(path, "the reader failed" + (what.empty() ? std::string() : ": " + what));
  };
  // Parses the XML and reads the pieces' sizes; no array is created yet. What VTK
  // sizes its work by is checked before the data are read. VTK throws
  // std::bad_alloc from deep inside the reader when a size the file gives in its
  // data (a compression header's block count, say) cannot be allocated.
  try {
    reader->UpdateInformation();
    refuse_on_errors();
    if (vtkXMLDataParser* parser = reader->GetXMLParser()) {
      check_declared_sizes(path, parser->GetRootElement(), max_items_for(path));
      check_data(path, parser, max_items_for(path));
      refuse_on_errors();
    }
    reader->Update();
  } catch (const std::bad_alloc&) {
    fail(path, "the reader ran out of memory: the file declares more data than it holds or than memory allows");
  }
  refuse_on_errors();
  vtkUnstructuredGrid* grid = reader->GetOutput();
  if (grid == nullptr) fail(path, "the reader produced no grid");

  const vtkIdType n_points = grid->GetNumberOfPoints();
  if (n_points == 0 || grid->GetPoints() == nullptr) fail(path, "the grid has no points");
  if (n_points > std::numeric_limits<std::int32_t>::max()) {
    fail(path, "the grid has " + std::to_string(n_points) + " points, more than a cloud can hold");
  }
  const CellView cells = view_cells(path, grid->GetCells());
  check_cells(path, cells, grid->GetCellTypesArray(), n_points);

  Cloud cloud;
  cloud.name = path;
  cloud.X.resize(n_points);
  for (vtkIdType p = 0; p < n_points; ++p) {
    double x[3];
    grid->GetPoint(p, x);
    if (!std::isfinite(x[0]) || !std::isfinite(x[1]) || !std::isfinite(x[2])) {
      std::ostringstream msg;
      msg << "point " << p << " has a non-finite coordinate (" << x[0] << ", " << x[1] << ", " << x[2] << ")";
      fail(path, msg.str());
    }
    cloud.X[p] = Vec3(x[0], x[1], x[2]);
  }
  const vtkIdType n_cells = cells.n_offsets - 1;
  for (vtkIdType c = 0; c < n_cells; ++c) {
    std::int32_t nodes[8];
    const std::int64_t begin = cells.offset(c);
    for (std::int64_t k = 0; k < cells.offset(c + 1) - begin; ++k) {
      nodes[k] = static_cast<std::int32_t>(cells.id(begin + k));
    }
    const int type = grid->GetCellTypesArray()->GetValue(c);
    cloud.mesh.add_element(type == VTK_TETRA ? ElementType::Tet4 : ElementType::Hex8, nodes);
  }

  // Inverted cells are the usual defect of exported meshes (node order of a
  // mirrored part): report how many, not only the first, before finalize_cloud.
  int inverted = 0, first_inverted = -1;
  for (int e = 0; e < cloud.mesh.n_elements(); ++e) {
    if (!(element_min_scaled_jacobian(cloud, e) > 0.0)) {
      if (inverted++ == 0) first_inverted = e;
    }
  }
  if (inverted > 0) {
    fail(path, std::to_string(inverted) + " of " + std::to_string(cloud.mesh.n_elements()) +
                   " cells are inverted or degenerate (first: cell " + std::to_string(first_inverted) +
                   "); expected VTK node order with positive volume");
  }

  // The file carries no surface names: the whole surface is "surface".
  cloud.surface_names = {"surface"};
  finalize_cloud(cloud);
  for (const std::int32_t p : cloud.boundary_particles) cloud.surface_mask[p] = 1;
  return cloud;
}

}  // namespace rkpm::particles
