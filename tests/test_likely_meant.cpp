// likelyMeant: the name a misspelt key or section most likely stands for,
// by edit distance -- and no guess where none is near or two are as near.

#include <gtest/gtest.h>
#include <lvfusion/common/LikelyMeant.h>

using lvf::common::didYouMean;
using lvf::common::likelyMeant;

namespace
{
const std::vector<std::string> kKeys = {"z_min", "z_max", "d_allow", "window_size", "robot_height", "accept_ncc"};
}

TEST(LikelyMeant, FindsTheKeyOneOrTwoEditsAway)
{
	EXPECT_EQ(likelyMeant("z_mx", kKeys), "z_max");	 // a deletion
	EXPECT_EQ(likelyMeant("windw_sise", kKeys), "window_size");	 // a deletion and a substitution
	EXPECT_EQ(likelyMeant("robot_hieght", kKeys), "robot_height");	 // a swap counts as one edit
	EXPECT_EQ(likelyMeant("ROBOT_HEIGHT", kKeys), "robot_height");	 // case is ignored
	EXPECT_EQ(likelyMeant("accept_nccc", kKeys), "accept_ncc");	 // an insertion
}

TEST(LikelyMeant, GuessesNothingFarOrAmbiguous)
{
	EXPECT_EQ(likelyMeant("colour", kKeys), "");
	EXPECT_EQ(likelyMeant("window", kKeys), "");  // five edits away
	EXPECT_EQ(likelyMeant("z_mix", kKeys), "");	 // one edit from z_min and from z_max
	EXPECT_EQ(likelyMeant("zz", kKeys), "");  // too short for a guess to mean anything
	EXPECT_EQ(likelyMeant("", kKeys), "");
	EXPECT_EQ(likelyMeant("z_max", {}), "");
}

TEST(LikelyMeant, DidYouMeanIsTheSuffixOfAnUnknownKeyMessage)
{
	EXPECT_EQ(didYouMean("d_alow", kKeys), " (did you mean 'd_allow'?)");
	EXPECT_EQ(didYouMean("colour", kKeys), "");
}
