// Rectangle: parsing of "x0,y0,x1,y1", validation, side geometry and snapping.
#include "core/geometry/Rectangle.hpp"

#include <gtest/gtest.h>

#include <ostream>

#include <cmath>
#include <limits>
#include <string>

#include "core/util/Errors.hpp"

namespace vorodg {

namespace {

TEST(Rectangle, ParseAcceptsFourCommaSeparatedNumbers) {
  const Rectangle r = Rectangle::parse("0,0,4,1");
  EXPECT_EQ(r.x0(), 0.0);
  EXPECT_EQ(r.y0(), 0.0);
  EXPECT_EQ(r.x1(), 4.0);
  EXPECT_EQ(r.y1(), 1.0);
  EXPECT_EQ(r.width(), 4.0);
  EXPECT_EQ(r.height(), 1.0);
  EXPECT_EQ(r.area(), 4.0);
  EXPECT_EQ(r.scale(), 4.0);
}

TEST(Rectangle, ParseAcceptsNegativeAndFractionalCoordinates) {
  const Rectangle r = Rectangle::parse("-1.5,-2,0.25,3e-1");
  EXPECT_EQ(r.x0(), -1.5);
  EXPECT_EQ(r.y0(), -2.0);
  EXPECT_EQ(r.x1(), 0.25);
  EXPECT_EQ(r.y1(), 0.3);
  EXPECT_DOUBLE_EQ(r.area(), 1.75 * 2.3);
}

TEST(Rectangle, ParseRejectsInvertedOrMalformedText) {
  for (const std::string bad : {"1,0,0,1", "0,1,1,0", "0,0,0,1", "a,b", "0,0,1", "0,0,1,1,2", "",
                                "0,0,1,x", "0,,1,1", "nan,0,1,1", "0,0,inf,1"}) {
    SCOPED_TRACE("text: '" + bad + "'");
    EXPECT_THROW(Rectangle::parse(bad), InputError);
  }
}

TEST(Rectangle, ParseErrorMessageNamesTheText) {
  try {
    Rectangle::parse("a,b");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("a,b"), std::string::npos) << e.what();
  }
}

TEST(Rectangle, ConstructorRejectsEmptyAndNonFiniteBoxes) {
  const double inf = std::numeric_limits<double>::infinity();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(Rectangle(0, 0, 0, 1), InputError);
  EXPECT_THROW(Rectangle(0, 0, 1, 0), InputError);
  EXPECT_THROW(Rectangle(1, 0, 0, 1), InputError);
  EXPECT_THROW(Rectangle(0, 0, inf, 1), InputError);
  EXPECT_THROW(Rectangle(nan, 0, 1, 1), InputError);
  EXPECT_NO_THROW(Rectangle(0, 0, 1e-9, 1e-9));
}

TEST(Rectangle, SideNamesAndCoordinates) {
  const Rectangle r(1, 2, 5, 3);
  EXPECT_EQ(side_name(Side::left), "left");
  EXPECT_EQ(side_name(Side::right), "right");
  EXPECT_EQ(side_name(Side::bottom), "bottom");
  EXPECT_EQ(side_name(Side::top), "top");
  EXPECT_EQ(side_name(Side::none), "none");
  EXPECT_EQ(r.side_coordinate(Side::left), 1.0);
  EXPECT_EQ(r.side_coordinate(Side::right), 5.0);
  EXPECT_EQ(r.side_coordinate(Side::bottom), 2.0);
  EXPECT_EQ(r.side_coordinate(Side::top), 3.0);
  const Point p(2.0, 2.25);
  EXPECT_DOUBLE_EQ(r.distance_to_side(p, Side::left), 1.0);
  EXPECT_DOUBLE_EQ(r.distance_to_side(p, Side::right), 3.0);
  EXPECT_DOUBLE_EQ(r.distance_to_side(p, Side::bottom), 0.25);
  EXPECT_DOUBLE_EQ(r.distance_to_side(p, Side::top), 0.75);
}

TEST(Rectangle, SidesNearFindsOneSideOnAnEdgeAndTwoAtACorner) {
  const Rectangle r(0, 0, 4, 1);
  const double tol = 1e-8 * r.scale();
  auto count = [](const std::array<bool, 4>& a) { return a[0] + a[1] + a[2] + a[3]; };

  const auto interior = r.sides_near(Point(2, 0.5), tol);
  EXPECT_EQ(count(interior), 0);

  const auto bottom = r.sides_near(Point(2, 0.5 * tol), tol);
  EXPECT_EQ(count(bottom), 1);
  EXPECT_TRUE(bottom[static_cast<int>(Side::bottom)]);

  const auto corner = r.sides_near(Point(4, 1), tol);
  EXPECT_EQ(count(corner), 2);
  EXPECT_TRUE(corner[static_cast<int>(Side::right)]);
  EXPECT_TRUE(corner[static_cast<int>(Side::top)]);

  const auto just_outside_tol = r.sides_near(Point(2, 2 * tol), tol);
  EXPECT_EQ(count(just_outside_tol), 0);
}

TEST(Rectangle, CommonSideOfTwoPoints) {
  const Rectangle r(0, 0, 4, 1);
  const double tol = 1e-8 * r.scale();
  EXPECT_EQ(r.common_side(Point(0, 0.2), Point(0, 0.7), tol), Side::left);
  EXPECT_EQ(r.common_side(Point(4, 0.2), Point(4, 1), tol), Side::right);
  EXPECT_EQ(r.common_side(Point(1, 0), Point(2, 0), tol), Side::bottom);
  EXPECT_EQ(r.common_side(Point(0, 1), Point(3, 1), tol), Side::top);
  // Two points on different sides (a diagonal through the domain) share no side.
  EXPECT_EQ(r.common_side(Point(0, 0.5), Point(2, 1), tol), Side::none);
  EXPECT_EQ(r.common_side(Point(1, 0.5), Point(2, 0.5), tol), Side::none);
  // Within the tolerance counts as on the side.
  EXPECT_EQ(r.common_side(Point(1, 0.1 * tol), Point(2, -0.1 * tol), tol), Side::bottom);
}

TEST(Rectangle, ContainsWithTolerance) {
  const Rectangle r(0, 0, 4, 1);
  EXPECT_TRUE(r.contains(Point(2, 0.5), 0.0));
  EXPECT_TRUE(r.contains(Point(0, 0), 0.0));
  EXPECT_TRUE(r.contains(Point(4, 1), 0.0));
  EXPECT_FALSE(r.contains(Point(4 + 1e-6, 1), 0.0));
  EXPECT_TRUE(r.contains(Point(4 + 1e-6, 1), 1e-5));
  EXPECT_FALSE(r.contains(Point(-1e-3, 0.5), 1e-5));
}

TEST(Rectangle, SnapMovesPointsExactlyOntoNearbySides) {
  const Rectangle r(0, 0, 4, 1);
  const double tol = 1e-8 * r.scale();
  const Point on_right = r.snap(Point(4 - 0.5 * tol, 0.3), tol);
  EXPECT_EQ(on_right.x(), 4.0);
  EXPECT_EQ(on_right.y(), 0.3);

  const Point corner = r.snap(Point(0.5 * tol, 1 + 0.5 * tol), tol);
  EXPECT_EQ(corner.x(), 0.0);
  EXPECT_EQ(corner.y(), 1.0);

  const Point interior(2.0, 0.5);
  EXPECT_EQ(r.snap(interior, tol), interior);

  const Point farther(4 - 3 * tol, 0.3);
  EXPECT_EQ(r.snap(farther, tol), farther);
}

TEST(Rectangle, ToStringRoundTripsThroughParse) {
  const Rectangle r(0.1, -0.2, 1.0 / 3.0, 2.0 / 3.0);
  const Rectangle back = Rectangle::parse(r.to_string());
  EXPECT_EQ(back.x0(), r.x0());
  EXPECT_EQ(back.y0(), r.y0());
  EXPECT_EQ(back.x1(), r.x1());
  EXPECT_EQ(back.y1(), r.y1());
}

}  // namespace
}  // namespace vorodg
