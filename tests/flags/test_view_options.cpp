// The shared option groups through CLI11, as every command parses them: values reach the structs, bad values
// give the one message format naming the flag and the accepted range, a missing value says what was
// expected, and the help is generated from the groups.
#include <catch2/catch.hpp>
#include <glm/gtc/constants.hpp>
#include <string>
#include <vector>

#include "flags/flag_values.h"
#include "flags/view_options.h"

using namespace raycam;

namespace {
struct Parsed {
  ViewFlags view;
  CastOptions cast;
  AccuracyFlags accuracy;
};

// Parses like a command that renders; returns "" or the error message the user would see.
std::string parse(std::vector<std::string> args, Parsed& out) {
  CLI::App command("test", "render");
  flags::add_view_options(command, out.view);
  flags::add_caster_options(command, out.cast, out.accuracy);
  try {
    command.parse(std::vector<std::string>(args.rbegin(), args.rend()));
  } catch (const CLI::Error& error) {
    return flags::usage_error_message(command, error);
  }
  return "";
}

std::string error_of(std::vector<std::string> args) {
  Parsed parsed;
  return parse(std::move(args), parsed);
}
}  // namespace

TEST_CASE("camera flags reach the view setup, in degrees, flags over the preset", "[flags][view]") {
  Parsed p;
  REQUIRE(parse({"--mode", "3d", "--theta", "90", "--phi", "90", "--d", "4", "--size", "20x10", "--target",
                 "0,0,0", "--df", "1.5", "--res", "0.5"},
                p) == "");
  CHECK(p.view.dimension == 3);
  CHECK(p.view.camera.theta_deg == 90.0);
  CHECK(p.view.camera.size == std::vector<int>{20, 10});
  const ViewSetup setup = make_view_setup(p.view);
  CHECK(setup.camera3d.orbit().theta == Approx(glm::half_pi<double>()));
  CHECK(setup.camera3d.max_columns() == 20);
  CHECK(setup.camera3d.max_rows() == 10);
  CHECK(setup.camera3d.orbit().df == 1.5);
  CHECK(glm::length(setup.camera3d.screen_centre() - glm::dvec3(0, 4, 0)) < 1e-12);

  Parsed two;
  REQUIRE(parse({"--view", "2d", "--size", "50", "--res", "0.5", "--theta", "-30"}, two) == "");
  CHECK(make_view_setup(two.view).camera2d.pixel_count() == 25);
  CHECK(two.view.camera.theta_deg == -30.0);  // a negative number is a value, not an option

  Parsed last;
  REQUIRE(parse({"--d", "3", "--d", "5"}, last) == "");
  CHECK(last.view.camera.d == 5.0);  // given twice: the last wins
}

TEST_CASE("a bad value names the flag, the accepted range and what was given", "[flags][view]") {
  CHECK(error_of({"--res", "0"}) == "--res: expected a number in ]0, 1], got '0'");
  CHECK(error_of({"--res", "1.5"}) == "--res: expected a number in ]0, 1], got '1.5'");
  CHECK(error_of({"--d", "-3"}) == "--d: expected a number in ]0, 1e12], got '-3'");
  CHECK(error_of({"--d", "0"}) == "--d: expected a number in ]0, 1e12], got '0'");
  CHECK(error_of({"--df", "0"}) == "--df: expected a number in [1e-9, 1e9], got '0'");
  CHECK(error_of({"--theta", "nan"}) == "--theta: expected an angle in degrees in [-1e6, 1e6], got 'nan'");
  CHECK(error_of({"--phi", "1e999"}) == "--phi: expected an angle in degrees in [-1e6, 1e6], got '1e999'");
  CHECK(error_of({"--mode", "4d"}) == "--mode: expected 2d or 3d, got '4d'");
  CHECK(error_of({"--method", "fast"}) ==
        "--method: expected automatic, plain, culled, footprint or binned, got 'fast'");
  CHECK(error_of({"--threads", "0"}) == "--threads: expected an integer in [1, 256], got '0'");
  CHECK(error_of({"--precision", "half"}) ==
        "--precision: expected float, double or long-double, got 'half'");
  CHECK(error_of({"--spp", "4x"}) == "--spp: expected an integer in [1, 65536], got '4x'");
  for (const char* size : {"0x5", "100000x100000", "3x4x5", "x"})
    CHECK(error_of({"--size", size}).rfind("--size: expected N in [1, 1048576] or WxH", 0) == 0);
  CHECK(error_of({"--target", "1,2,3,4"}).rfind("--target: expected x,y or x,y,z", 0) == 0);
}

TEST_CASE("in-range subnormals are accepted", "[flags][view]") {
  Parsed p;
  REQUIRE(parse({"--phi", "2.8e-322", "--theta", "-4.9e-324"}, p) == "");
  CHECK(*p.view.camera.phi_deg == 2.8e-322);
  CHECK(*p.view.camera.theta_deg == -4.9e-324);
  CHECK_NOTHROW(make_view_setup(p.view));
}

TEST_CASE("a missing value says what was expected", "[flags][view]") {
  CHECK(error_of({"--threads"}) == "--threads: expected an integer in [1, 256], got nothing");
  CHECK(error_of({"--d"}) == "--d: expected a number in ]0, 1e12], got nothing");
  // CLI11 takes the next word as the value, whatever it looks like: the message shows it.
  CHECK(error_of({"--res", "--d", "2"}) == "--res: expected a number in ]0, 1], got '--d'");
}

TEST_CASE("an unknown option is named", "[flags][view]") {
  CHECK(error_of({"--frobnicate"}) == "unknown option '--frobnicate' (see render --help)");
}

TEST_CASE("the accuracy knobs reach the reference caster's options", "[flags][accuracy]") {
  Parsed p;
  REQUIRE(parse({"--precision", "float", "--intersect", "naive", "--spp", "16", "--frame", "relative",
                 "--placement", "arccos", "--exact", "--method", "binned", "--threads", "3"},
                p) == "");
  CHECK(p.accuracy.options.scalar == Scalar::float32);
  CHECK(p.accuracy.options.formula == IntersectFormula::naive);
  CHECK(p.accuracy.options.samples_per_pixel == 16);
  CHECK(p.accuracy.options.camera_relative);
  CHECK(p.accuracy.placement == PlacementRoute::arccos);
  CHECK(p.accuracy.exact);
  CHECK(p.cast.method == CastMethod::binned);
  CHECK(p.cast.threads == 3);

  Parsed none;
  REQUIRE(parse({"--method", "plain"}, none) == "");
  CHECK(none.accuracy.options.scalar == Scalar::float64);  // --method is not an accuracy knob
  CHECK(none.accuracy.options.samples_per_pixel == 1);
  CHECK_FALSE(none.accuracy.exact);
}

TEST_CASE("the help is generated from the groups, every flag in it", "[flags][help]") {
  Parsed p;
  CLI::App command("test", "render");
  flags::add_view_options(command, p.view);
  flags::add_caster_options(command, p.cast, p.accuracy);
  const std::string help = command.help();
  for (const char* flag :
       {"Camera",      "Caster",      "--scene", "--mode",  "--view",      "--target", "--d",
        "--theta",     "--phi",       "--df",    "--res",   "--size",      "--method", "--threads",
        "--precision", "--intersect", "--spp",   "--frame", "--placement", "--exact"})
    CHECK(help.find(flag) != std::string::npos);
}

TEST_CASE("what depends on the scene is checked by make_view_setup, naming the flag", "[flags][view]") {
  const auto setup_error = [](std::vector<std::string> args) -> std::string {
    Parsed p;
    REQUIRE(parse(std::move(args), p) == "");
    try {
      make_view_setup(p.view);
    } catch (const std::invalid_argument& error) {
      return error.what();
    }
    return "";
  };
  CHECK_THAT(setup_error({"--mode", "2d", "--phi", "3"}), Catch::StartsWith("--phi"));
  CHECK_THAT(setup_error({"--mode", "2d", "--target", "1,2,3"}), Catch::StartsWith("--target"));
  CHECK_THAT(setup_error({"--mode", "3d", "--target", "1,2"}), Catch::StartsWith("--target"));
  CHECK_THAT(setup_error({"--mode", "2d", "--size", "4x4"}), Catch::StartsWith("--size"));
}
