#pragma once
/// Timed interactions for a live simulation (`hooke view --script FILE`): what a user does with the mouse and the
/// panel, replayed at given simulated times so that a run can be tested and recorded. One command per line:
///
///     # time (s of simulated time), command, arguments; '#' starts a comment
///     0.00 grab 17 18              grab nodes (model numbering)
///     0.00 grab-nearest 0 0 0.1    grab the node nearest to a point, m
///     0.01 drag 0 0 0.003 over 0.5 drive the grabbed nodes to grab position + (dx, dy, dz) m, ramped over 0.5 s
///     0.60 release
///     0.00 tool sphere:0.005 0 0 0.03        a rigid tool (sphere:R, capsule:R,L in m) at a position, m; optional
///                                            "friction MU"; "tool none" takes it away (docs/contact.md)
///     0.01 move-tool 0 0 0.022 over 0.3      move it to a position, m, ramped over 0.3 s (0: at once)
///     0.70 set poisson 0.45        set young|poisson|density|method|integrator|dt|damping-mass|damping-stiffness|
///                                  influence-radius|gravity (on|off)
///     0.70 reset | pause | resume
///     0.80 colormap error          none|displacement|error|strain|weights (drawing)
///     0.80 ghost linear            off|linear|stvk: the FEM ghost (drawing)
///     0.90 screenshot out.png      write the next drawn frame (drawing)
///     1.00 quit
///
/// Times must not decrease. Physics commands run in the physics thread before the first step at or after their
/// time; drawing commands are handed to the front end at that time, and the physics waits for it (so a screenshot
/// shows the state at the command's time).
#include <hooke/core/types.hpp>
#include <string>
#include <vector>

namespace hooke::interactive {

enum class ScriptAction {
  kGrab,
  kGrabNearest,
  kDrag,
  kRelease,
  kTool,
  kMoveTool,
  kSet,
  kReset,
  kPause,
  kResume,
  kColormap,
  kGhost,
  kScreenshot,
  kQuit
};

struct ScriptCommand {
  double time = 0.0;  ///< simulated time, s (>= 0)
  ScriptAction action = ScriptAction::kQuit;
  std::vector<int> nodes;      ///< grab
  Vec3 vector = Vec3::Zero();  ///< grab-nearest: point, m; drag: offset, m; tool, move-tool: position, m
  double duration = 0.0;       ///< drag, move-tool: ramp time, s (0: at once)
  double friction = 0.0;       ///< tool: Coulomb coefficient
  std::string key;             ///< set: what; colormap / ghost: the choice; screenshot: the file; tool: the shape
  std::string value;           ///< set: the value as written
  int line = 0;                ///< 1-based line in the file
};

/// True for the commands the front end carries out (colormap, ghost, screenshot, quit).
bool is_drawing(ScriptAction action);

/// Parses a script. `source` names the text in messages.
/// @throws ParseError naming source and line for an unknown command, a bad number, a missing argument or a time
///   that decreases
std::vector<ScriptCommand> parse_script(const std::string& text, const std::string& source);
/// Reads and parses a script file. @throws IoError when it cannot be read, ParseError as parse_script
std::vector<ScriptCommand> read_script(const std::string& path);

}  // namespace hooke::interactive
