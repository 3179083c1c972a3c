// A 100,000-gon twisted at 25,000 slices: 2.5·10^9 mesh vertices, counted
// as steps before any is made (a circle is a smooth one's 256-gon here).
linear_extrude(height = 1, twist = 90, slices = 25000)
    polygon([for (i = [0:99999]) 1e6 * [cos(i * 360 / 100000), sin(i * 360 / 100000)]]);
