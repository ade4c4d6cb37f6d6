// Quarter plate with a circular hole (the plate_hole.toml example, drawn in Gmsh).
// Every boundary curve has a physical name; gmsh_plate_hole.toml reads the conditions
// by these names. Two curves are drawn against the body's orientation on purpose (CD from
// D to C, the hole from A to E): bemcontact turns them so that the plate is on their left.
a = 1.0;
W = 20.0;
Point(1) = {a, 0, 0};   // A
Point(2) = {W, 0, 0};   // B
Point(3) = {W, W, 0};   // C
Point(4) = {0, W, 0};   // D
Point(5) = {0, a, 0};   // E
Point(6) = {0, 0, 0};   // centre of the hole
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {4, 3};
Line(4) = {4, 5};
Circle(5) = {1, 6, 5};
// Element counts and gradings of plate_hole.toml: 40 = ratio of the longest to the
// shortest element, short ones at the hole.
Transfinite Curve {1} = 15 Using Progression 40^(1/13);
Transfinite Curve {2} = 7;
Transfinite Curve {3} = 9;
Transfinite Curve {4} = 15 Using Progression 40^(-1/13);
Transfinite Curve {5} = 31;
Physical Curve("AB") = {1};
Physical Curve("BC") = {2};
Physical Curve("CD") = {3};
Physical Curve("DE") = {4};
Physical Curve("hole") = {5};
