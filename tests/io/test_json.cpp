// summary.json (written through nlohmann/json): the text must be valid JSON (checked
// by a small strict parser written here, independent of the writer), numbers must read back exactly,
// strings must be escaped, and non-finite numbers must be refused.
#include "io_test_support.hpp"

#include "rkpm/io/json.hpp"
#include "rkpm/io/run_summary.hpp"

#include <charconv>
#include <cstring>
#include <limits>
#include <map>
#include <memory>

namespace rkpm::io::test {
namespace {

// Strict RFC 8259 parser into a tagged tree; throws on anything malformed.
struct Node {
  enum class Kind { null, boolean, number, string, array, object } kind = Kind::null;
  bool boolean = false;
  double number = 0.0;
  std::string text;  // string value
  std::vector<Node> items;
  std::vector<std::pair<std::string, Node>> members;
  const Node& at(const std::string& key) const {
    for (const auto& [k, v] : members)
      if (k == key) return v;
    throw std::out_of_range("no key " + key);
  }
};

class Parser {
 public:
  explicit Parser(std::string s) : s_(std::move(s)) {}
  Node parse() {
    Node n = value();
    skip_ws();
    if (pos_ != s_.size()) fail("trailing characters");
    return n;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw std::runtime_error(what + " at offset " + std::to_string(pos_));
  }
  void skip_ws() {
    while (pos_ < s_.size() && std::strchr(" \t\n\r", s_[pos_]) != nullptr) ++pos_;
  }
  bool consume(const char* word) {
    const std::size_t n = std::strlen(word);
    if (s_.compare(pos_, n, word) != 0) return false;
    pos_ += n;
    return true;
  }
  void expect(char c) {
    skip_ws();
    if (pos_ >= s_.size() || s_[pos_] != c) fail(std::string("expected '") + c + "'");
    ++pos_;
  }
  Node value() {
    skip_ws();
    if (pos_ >= s_.size()) fail("unexpected end");
    Node n;
    const char c = s_[pos_];
    if (consume("null")) return n;
    if (consume("true") || consume("false")) {
      n.kind = Node::Kind::boolean;
      n.boolean = s_[pos_ - 1] == 'e' && s_[pos_ - 2] == 'u';
      return n;
    }
    if (c == '"') {
      n.kind = Node::Kind::string;
      n.text = string();
      return n;
    }
    if (c == '[') {
      n.kind = Node::Kind::array;
      ++pos_;
      skip_ws();
      if (pos_ < s_.size() && s_[pos_] == ']') return ++pos_, n;
      do n.items.push_back(value());
      while (skip_ws(), pos_ < s_.size() && s_[pos_] == ',' && ++pos_);
      expect(']');
      return n;
    }
    if (c == '{') {
      n.kind = Node::Kind::object;
      ++pos_;
      skip_ws();
      if (pos_ < s_.size() && s_[pos_] == '}') return ++pos_, n;
      do {
        skip_ws();
        std::string key = string();
        expect(':');
        n.members.emplace_back(std::move(key), value());
      } while (skip_ws(), pos_ < s_.size() && s_[pos_] == ',' && ++pos_);
      expect('}');
      return n;
    }
    n.kind = Node::Kind::number;
    n.number = number();
    return n;
  }
  double number() {
    // JSON grammar: -?(0|[1-9][0-9]*)(\.[0-9]+)?([eE][+-]?[0-9]+)?
    const std::size_t start = pos_;
    auto digits = [&] {
      const std::size_t d = pos_;
      while (pos_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[pos_]))) ++pos_;
      if (pos_ == d) fail("expected digits");
    };
    if (s_[pos_] == '-') ++pos_;
    if (pos_ < s_.size() && s_[pos_] == '0') {
      ++pos_;
    } else {
      digits();
    }
    if (pos_ < s_.size() && s_[pos_] == '.') ++pos_, digits();
    if (pos_ < s_.size() && (s_[pos_] == 'e' || s_[pos_] == 'E')) {
      ++pos_;
      if (pos_ < s_.size() && (s_[pos_] == '+' || s_[pos_] == '-')) ++pos_;
      digits();
    }
    double x = 0.0;
    std::from_chars(s_.data() + start, s_.data() + pos_, x);
    return x;
  }
  std::string string() {
    if (pos_ >= s_.size() || s_[pos_] != '"') fail("expected string");
    ++pos_;
    std::string out;
    while (true) {
      if (pos_ >= s_.size()) fail("unterminated string");
      const char c = s_[pos_++];
      if (c == '"') return out;
      if (static_cast<unsigned char>(c) < 0x20) fail("raw control character in string");
      if (c != '\\') {
        out += c;
        continue;
      }
      const char e = s_[pos_++];
      switch (e) {
        case '"': out += '"'; break;
        case '\\': out += '\\'; break;
        case '/': out += '/'; break;
        case 'n': out += '\n'; break;
        case 't': out += '\t'; break;
        case 'r': out += '\r'; break;
        case 'b': out += '\b'; break;
        case 'f': out += '\f'; break;
        case 'u': {
          unsigned code = 0;
          std::from_chars(s_.data() + pos_, s_.data() + pos_ + 4, code, 16);
          pos_ += 4;
          if (code >= 0x80) fail("test parser handles only ASCII \\u escapes");
          out += static_cast<char>(code);
          break;
        }
        default: fail("bad escape");
      }
    }
  }

  std::string s_;
  std::size_t pos_ = 0;
};

std::uint64_t bits(double x) {
  std::uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

TEST(Json, CompactTextIsExactlyAsExpected) {
  Json j = Json::object();
  j.set("a", 1).set("b", Json::Array{true, false, nullptr}).set("c", "x").set("d", 0.5).set("e", Json::object());
  j.set("a", -7);  // replaces, keeps position
  EXPECT_EQ(j.dump(0), R"({"a":-7,"b":[true,false,null],"c":"x","d":0.5,"e":{}})");
  EXPECT_EQ(Json::array().dump(0), "[]");
  EXPECT_EQ(Json(std::int64_t{-9007199254740993}).dump(), "-9007199254740993");  // not squeezed through a double
}

TEST(Json, IndentedTextIsExactlyAsExpected) {
  Json j = Json::object();
  j.set("n", 3).set("list", Json::Array{1, 2});
  EXPECT_EQ(j.dump(2), "{\n  \"n\": 3,\n  \"list\": [\n    1,\n    2\n  ]\n}");
}

TEST(Json, StringsAreEscaped) {
  const std::string nasty = std::string("quote \" backslash \\ newline \n tab \t cr \r bell \x07 nul-free \x01 é");
  EXPECT_EQ(json_quote(nasty), "\"quote \\\" backslash \\\\ newline \\n tab \\t cr \\r bell \\u0007 nul-free \\u0001 é\"");
  Json j = Json::object();
  j.set(nasty, nasty);
  const Node n = Parser(j.dump()).parse();
  ASSERT_EQ(n.members.size(), 1u);
  EXPECT_EQ(n.members[0].first, nasty);
  EXPECT_EQ(n.members[0].second.text, nasty);
}

// A name or path that is not valid UTF-8 (a scene file's bytes) is still written: its
// bad bytes become U+FFFD, never an exception that would lose the summary.
TEST(Json, InvalidUtf8IsReplacedNotRefused) {
  Json j = Json::object();
  j.set("scene", std::string("cell\xff\xfe.toml"));
  std::string text;
  ASSERT_NO_THROW(text = j.dump());
  const Node n = Parser(text).parse();
  EXPECT_EQ(n.at("scene").text, "cell\xef\xbf\xbd\xef\xbf\xbd.toml");
}

TEST(Json, NumbersReadBackBitForBit) {
  const std::vector<double> values = {0.1,     1.0 / 3.0, -2.5e-300, 5e-324, 1.7976931348623157e308, -0.0,
                                      1e22,    123456789012345678.0, 6.02214076e23, 1.0};
  Json array = Json::array();
  for (double v : values) array.push_back(v);
  const Node n = Parser(array.dump()).parse();
  ASSERT_EQ(n.items.size(), values.size());
  for (std::size_t k = 0; k < values.size(); ++k) {
    EXPECT_EQ(n.items[k].kind, Node::Kind::number);
    EXPECT_EQ(bits(n.items[k].number), bits(values[k])) << values[k];
  }
}

TEST(Json, NonFiniteNumbersAreRefusedWithTheirKeyPath) {
  Json j = Json::object();
  Json metrics = Json::object();
  metrics.set("energy", std::numeric_limits<double>::quiet_NaN());
  j.set("final_metrics", metrics);
  try {
    j.dump();
    FAIL() << "NaN was serialised";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("final_metrics.energy"), std::string::npos) << e.what();
  }
  Json list = Json::Array{1.0, std::numeric_limits<double>::infinity()};
  EXPECT_THROW(list.dump(), std::invalid_argument);
  EXPECT_THROW(Json(1).set("k", 2), std::logic_error);
  EXPECT_THROW(Json("s").push_back(2), std::logic_error);
  EXPECT_THROW(Json(std::numeric_limits<std::uint64_t>::max()), std::out_of_range);
}

using RunSummaryTest = ScratchDir;

TEST_F(RunSummaryTest, SummaryFileParsesWithEveryField) {
  RunSummary s;
  s.scene = "scenes/cell \"A\".toml";
  s.particle_counts = {{"cell", 1200}, {"substrate", 800}};
  s.steps = 40000;
  s.simulated_time = 2.0e-3;
  s.wall_time = 12.75;
  s.frames_written = 21;
  s.final_metrics = {{"kinetic_energy", 1.25e-9}, {"max_von_mises", 345.5}};
  const auto path = dir / "summary.json";
  write_summary(path, s);

  const Node n = Parser(read_text(path)).parse();
  EXPECT_EQ(n.at("scene").text, s.scene);
  EXPECT_EQ(n.at("particle_counts").at("cell").number, 1200.0);
  EXPECT_EQ(n.at("particle_counts").at("substrate").number, 800.0);
  EXPECT_EQ(n.at("total_particles").number, 2000.0);
  EXPECT_EQ(n.at("steps").number, 40000.0);
  EXPECT_EQ(n.at("simulated_time").number, 2.0e-3);
  EXPECT_EQ(n.at("wall_time").number, 12.75);
  EXPECT_EQ(n.at("frames_written").number, 21.0);
  EXPECT_EQ(n.at("status").text, "completed");
  EXPECT_EQ(n.at("final_metrics").at("kinetic_energy").number, 1.25e-9);
  EXPECT_EQ(n.at("final_metrics").at("max_von_mises").number, 345.5);
}

TEST_F(RunSummaryTest, NonFiniteMetricLeavesPreviousSummary) {
  const auto path = dir / "summary.json";
  RunSummary good;
  good.scene = "a.toml";
  write_summary(path, good);
  const std::string before = read_text(path);
  RunSummary bad = good;
  bad.final_metrics = {{"kinetic_energy", std::numeric_limits<double>::infinity()}};
  EXPECT_THROW(write_summary(path, bad), std::invalid_argument);
  EXPECT_EQ(read_text(path), before);
  EXPECT_EQ(file_names(dir), std::set<std::string>{"summary.json"});
}

}  // namespace
}  // namespace rkpm::io::test
