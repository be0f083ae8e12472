// tide serve's command messages (tide/serve/command.hpp): each command read, and every way a
// message can be wrong refused with a message that says what, or clamped to the documented limits.

#include <gtest/gtest.h>

#include <string>
#include <variant>

#include "tide/serve/command.hpp"

namespace tide::serve {
namespace {

template <class C>
C read(const std::string& text) {
  const ParsedCommand parsed = parse_command(text);
  EXPECT_TRUE(parsed.command.has_value()) << text << ": " << parsed.message;
  EXPECT_TRUE(parsed.command && std::holds_alternative<C>(*parsed.command)) << text;
  return parsed.command && std::holds_alternative<C>(*parsed.command) ? std::get<C>(*parsed.command) : C{};
}

// The refusal's message; fails when the message is read as a command.
std::string refusal(const std::string& text) {
  const ParsedCommand parsed = parse_command(text);
  EXPECT_FALSE(parsed.command.has_value()) << text;
  return parsed.message;
}

TEST(ServeCommand, ReadsEveryCommand) {
  EXPECT_EQ(read<SetViscosity>(R"({"command":"viscosity","value":0.001})").kinematic_viscosity, 0.001);
  const SetGravity gravity = read<SetGravity>(R"({"command":"gravity","magnitude":4.5,"tilt":-30})");
  EXPECT_EQ(gravity.magnitude, 4.5);
  EXPECT_EQ(gravity.tilt, -30);
  EXPECT_EQ(read<SetParticleCount>(R"({"command":"particles","value":5000})").count, 5000);
  EXPECT_TRUE(read<SetSurfaceTension>(R"({"command":"surface_tension","value":true})").on);
  EXPECT_EQ(read<SetScheme>(R"({"command":"scheme","value":"wcsph"})").scheme, scene::Scheme::wcsph);
  EXPECT_EQ(read<SetScheme>(R"({"command":"scheme","value":"dfsph"})").scheme, scene::Scheme::dfsph);
  EXPECT_EQ(read<SetColour>(R"({"command":"colour","value":"pressure"})").field, ColourField::pressure);
  EXPECT_FALSE(read<Pause>(R"({"command":"pause","value":false})").paused);
  read<Step>(R"({"command":"step"})");
  read<Reset>(R"({"command":"reset"})");
  const MoveObstacle move = read<MoveObstacle>(R"({"x":0.25,"command":"obstacle","y":-1})");
  EXPECT_EQ(move.x, 0.25);
  EXPECT_EQ(move.y, -1);
}

TEST(ServeCommand, ClampsNumbersToTheirLimitsAndSaysSo) {
  const ParsedCommand parsed = parse_command(R"({"command":"gravity","magnitude":1e9,"tilt":-500})");
  ASSERT_TRUE(parsed.command);
  const auto gravity = std::get<SetGravity>(*parsed.command);
  EXPECT_EQ(gravity.magnitude, CommandLimits::most_gravity);
  EXPECT_EQ(gravity.tilt, -CommandLimits::most_tilt);
  EXPECT_NE(parsed.message.find("magnitude 1e+09 clamped to 20"), std::string::npos) << parsed.message;
  EXPECT_NE(parsed.message.find("tilt -500 clamped to -180"), std::string::npos) << parsed.message;
  EXPECT_EQ(read<SetViscosity>(R"({"command":"viscosity","value":0})").kinematic_viscosity,
            CommandLimits::least_viscosity);
  EXPECT_EQ(read<SetParticleCount>(R"({"command":"particles","value":10000000000})").count,
            CommandLimits::most_particles);
  EXPECT_EQ(read<SetParticleCount>(R"({"command":"particles","value":-3})").count, CommandLimits::least_particles);
  EXPECT_TRUE(parse_command(R"({"command":"viscosity","value":0.001})").message.empty()) << "nothing to say";
}

TEST(ServeCommand, RefusesWhatIsNotACommand) {
  EXPECT_NE(refusal(R"({"command":"warp"})").find("unknown command \"warp\""), std::string::npos);
  EXPECT_NE(refusal(R"({"command":"viscosity"})").find("missing field \"value\""), std::string::npos);
  EXPECT_NE(refusal(R"({"command":"viscosity","value":"thick"})").find("must be a number"), std::string::npos);
  EXPECT_NE(refusal(R"({"command":"viscosity","value":1e-3,"unit":"cSt"})").find("unknown field \"unit\""),
            std::string::npos);
  EXPECT_NE(refusal(R"({"command":"particles","value":2.5})").find("must be an integer"), std::string::npos);
  EXPECT_NE(refusal(R"({"command":"pause","value":1})").find("true or false"), std::string::npos);
  EXPECT_NE(refusal(R"({"command":"scheme","value":"iisph"})").find("one of \"wcsph\", \"dfsph\""), std::string::npos);
  EXPECT_NE(refusal(R"({"command":"colour","value":3})").find("one of"), std::string::npos);
  EXPECT_NE(refusal(R"({"command":"step","value":1})").find("unknown field"), std::string::npos);
  EXPECT_NE(refusal(R"({"command":7})").find("string field \"command\""), std::string::npos);
  EXPECT_NE(refusal(R"([1, 2])").find("JSON object"), std::string::npos);
  EXPECT_FALSE(parse_command(R"({"command":"warp"})").garbage) << "a refused command keeps its connection";
}

TEST(ServeCommand, GarbageAndOversizedMessagesAreNotCommands) {
  for (const std::string& text : {std::string("not JSON"), std::string("{\"command\":"), std::string(""),
                                  std::string(largest_command_bytes + 1, ' ')}) {
    const ParsedCommand parsed = parse_command(text);
    EXPECT_FALSE(parsed.command);
    EXPECT_TRUE(parsed.garbage) << text.substr(0, 20);
  }
  // JSON's NaN and infinity do not parse; a number too large for a double does not either.
  EXPECT_TRUE(parse_command(R"({"command":"viscosity","value":NaN})").garbage);
  EXPECT_FALSE(parse_command(R"({"command":"viscosity","value":1e999})").command);
}

}  // namespace
}  // namespace tide::serve
