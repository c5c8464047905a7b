#include "tools/avc/help_formatter.h"

#include <gtest/gtest.h>

#include <memory>

namespace avc::cli {
namespace {

TEST(CommandSummary, AShortFirstSentenceIsKeptWhole) {
  EXPECT_EQ(CommandSummary("Calibrate the cell: intrinsics, hand-eye and turntable axis."),
            "Calibrate the cell: intrinsics, hand-eye and turntable axis");
  EXPECT_EQ(CommandSummary("Run the robot service. It obeys signed commands only."),
            "Run the robot service");
  EXPECT_EQ(CommandSummary("Print the version"), "Print the version");
}

TEST(CommandSummary, LineBreaksInsideTheSentenceReadAsSpaces) {
  EXPECT_EQ(CommandSummary("Store every product published\non the cell in a directory.\nMore."),
            "Store every product published on the cell in a directory");
}

TEST(CommandSummary, ALongFirstSentenceIsCutAtItsFirstClause) {
  const std::string description =
      "Merge and cluster a reconstruction offline (paper 3): the MVS points (points.ply) are\n"
      "merged into the plant proxy's voxels and clustered into surface patches.";
  EXPECT_EQ(CommandSummary(description), "Merge and cluster a reconstruction offline (paper 3)");
  const std::string no_clause(kSummaryLength + 20, 'x');
  EXPECT_EQ(CommandSummary(no_clause + ". Then more."), no_clause);
}

TEST(SummaryListingFormatter, ListsTheSummaryAndKeepsTheWholeDescriptionForTheCommand) {
  CLI::App app{"root"};
  app.formatter(std::make_shared<SummaryListingFormatter>());
  CLI::App* command = app.add_subcommand(
      "reconstruct",
      "Reconstruct a plant from images with known cameras: plant masks (automatic unless\n"
      "masks are given), the plant proxy and multi-view stereo points, merged and surfaced.");
  const std::string listing = app.help();
  EXPECT_NE(listing.find("Reconstruct a plant from images with known cameras\n"), std::string::npos)
      << listing;
  EXPECT_EQ(listing.find("masks are given"), std::string::npos) << listing;
  const std::string own = command->help();
  EXPECT_EQ(own.find(command->get_description()), 0u) << own;
}

}  // namespace
}  // namespace avc::cli
