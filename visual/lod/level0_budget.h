#pragma once
// Level0's triangle budget from the display (render.twolevel.level0_budget:
// "auto", the default). Level0 is static, so its vertical error e shows on
// screen as about e * p / d pixels at distance d, where p is the channel's
// pixels per radian: a telephoto channel needs a finer static mesh than a
// wide one for the same horizon error. The budget grows as sqrt(p) from
// 524 288 triangles at p = 887 (1024 rows over 60 degrees), the setting
// that measured best at both ends of the Table 2 flight: at 60 degrees
// 524 288 and at 15 degrees about 1 M triangles gave the best matched-error
// ratios against every baseline (docs/results.md, "Fourth round").

namespace ig::lod {

// Pixels per radian at the centre of a view of `rows` pixels over a vertical
// field of view of fov_y_deg degrees: rows / (2 tan(fov / 2)). The methods'
// screen-space errors use the same scale (render::pixels_per_radian).
double pixels_per_radian(int rows, double fov_y_deg);

// The auto budget for the finest channel's pixels per radian: rounded to
// 1024 triangles, within [32 768, 4 194 304]. Non-finite or non-positive
// input gives the reference budget.
int level0_budget_for_display(double pixels_per_radian);

}  // namespace ig::lod
