#include <charconv>
#include <cmath>
#include <fstream>
#include <hooke/contact/rigid_tool.hpp>
#include <hooke/core/error.hpp>
#include <hooke/interactive/fields.hpp>
#include <hooke/interactive/physics_loop.hpp>
#include <hooke/interactive/script.hpp>
#include <sstream>

namespace hooke::interactive {
namespace {

struct LineParser {
  const std::string& source;
  int line;
  std::vector<std::string> words;
  size_t next = 0;

  [[noreturn]] void fail(const std::string& what) const { throw ParseError(source, line, what); }

  const std::string& word(const char* what) {
    if (next >= words.size()) fail(std::string("missing ") + what);
    return words[next++];
  }
  double number(const char* what) {
    const std::string& w = word(what);
    double v = 0.0;
    const auto [end, ec] = std::from_chars(w.data(), w.data() + w.size(), v);
    if (ec != std::errc() || end != w.data() + w.size() || !std::isfinite(v))
      fail(std::string("'") + w + "' is not a finite number (" + what + ")");
    return v;
  }
  int integer(const char* what) {
    const std::string& w = word(what);
    int v = 0;
    const auto [end, ec] = std::from_chars(w.data(), w.data() + w.size(), v);
    if (ec != std::errc() || end != w.data() + w.size() || v < 0)
      fail(std::string("'") + w + "' is not a node number (" + what + ")");
    return v;
  }
  // "over SECONDS" when words are left: a ramp time (>= 0), else 0.
  double ramp() {
    if (next >= words.size()) return 0.0;
    if (word("'over'") != "over") fail("expected 'over SECONDS' after the position or offset");
    const double t = number("ramp time, s");
    if (t < 0.0) fail("the ramp time must be >= 0 s");
    return t;
  }
  void done() const {
    if (next < words.size()) fail("unexpected '" + words[next] + "'");
  }
};

}  // namespace

bool is_drawing(ScriptAction a) {
  return a == ScriptAction::kColormap || a == ScriptAction::kGhost || a == ScriptAction::kScreenshot ||
         a == ScriptAction::kQuit;
}

std::vector<ScriptCommand> parse_script(const std::string& text, const std::string& source) {
  std::vector<ScriptCommand> out;
  std::istringstream in(text);
  std::string raw;
  int line = 0;
  double last = 0.0;
  while (std::getline(in, raw)) {
    ++line;
    if (const size_t hash = raw.find('#'); hash != std::string::npos) raw.resize(hash);
    LineParser p{source, line, {}, 0};
    std::istringstream words(raw);
    for (std::string w; words >> w;) p.words.push_back(w);
    if (p.words.empty()) continue;
    ScriptCommand c;
    c.line = line;
    c.time = p.number("time, s");
    if (c.time < 0.0) p.fail("the time must be >= 0 s");
    if (c.time < last)
      p.fail("the times must not decrease (" + std::to_string(c.time) + " s after " + std::to_string(last) + " s)");
    last = c.time;
    const std::string verb = p.word("command");
    if (verb == "grab") {
      c.action = ScriptAction::kGrab;
      c.nodes.push_back(p.integer("node"));
      while (p.next < p.words.size()) c.nodes.push_back(p.integer("node"));
    } else if (verb == "grab-nearest") {
      c.action = ScriptAction::kGrabNearest;
      for (int a = 0; a < 3; ++a) c.vector(a) = p.number("coordinate, m");
    } else if (verb == "drag") {
      c.action = ScriptAction::kDrag;
      for (int a = 0; a < 3; ++a) c.vector(a) = p.number("offset, m");
      c.duration = p.ramp();
    } else if (verb == "tool") {
      c.action = ScriptAction::kTool;
      c.key = p.word("tool shape (sphere:R, capsule:R,L or none)");
      if (c.key != "none") {
        try {
          contact::parse_tool(c.key);
        } catch (const InvalidArgument& e) {
          p.fail(e.what());
        }
        for (int a = 0; a < 3; ++a) c.vector(a) = p.number("position, m");
        if (p.next < p.words.size()) {
          if (p.word("'friction'") != "friction") p.fail("expected 'friction MU' after the position");
          c.friction = p.number("friction coefficient");
          if (c.friction < 0.0) p.fail("the friction coefficient must be >= 0");
        }
      }
    } else if (verb == "move-tool") {
      c.action = ScriptAction::kMoveTool;
      for (int a = 0; a < 3; ++a) c.vector(a) = p.number("position, m");
      c.duration = p.ramp();
    } else if (verb == "release" || verb == "reset" || verb == "pause" || verb == "resume" || verb == "quit") {
      c.action = verb == "release"  ? ScriptAction::kRelease
                 : verb == "reset"  ? ScriptAction::kReset
                 : verb == "pause"  ? ScriptAction::kPause
                 : verb == "resume" ? ScriptAction::kResume
                                    : ScriptAction::kQuit;
    } else if (verb == "set") {
      c.action = ScriptAction::kSet;
      c.key = p.word("setting");
      c.value = p.word("value");
      try {  // the name and the value's form now, with the line; ranges when the physics applies it
        LiveSettings scratch;
        apply_setting(scratch, c.key, c.value);
      } catch (const InvalidArgument& e) {
        p.fail(e.what());
      }
    } else if (verb == "colormap") {
      c.action = ScriptAction::kColormap;
      c.key = p.word("colour map");
      try {  // the names of interactive::ColorField, one table
        color_field_from_name(c.key);
      } catch (const InvalidArgument& e) {
        p.fail(e.what());
      }
    } else if (verb == "ghost") {
      c.action = ScriptAction::kGhost;
      c.key = p.word("off, linear or stvk");
      if (c.key != "off" && c.key != "linear" && c.key != "stvk") p.fail("ghost takes off, linear or stvk");
    } else if (verb == "screenshot") {
      c.action = ScriptAction::kScreenshot;
      c.key = p.word("file");
    } else {
      p.fail("unknown command '" + verb + "'");
    }
    p.done();
    out.push_back(std::move(c));
  }
  return out;
}

std::vector<ScriptCommand> read_script(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  if (!f) throw IoError("cannot read the script " + path);
  std::stringstream buffer;
  buffer << f.rdbuf();
  if (f.bad()) throw IoError("cannot read the script " + path);
  return parse_script(buffer.str(), path);
}

}  // namespace hooke::interactive
