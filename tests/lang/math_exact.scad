// trigonometry exact at multiples of 30, 45 and 90 degrees
echo([for (a = [0 : 30 : 360]) sin(a)]);
echo([for (a = [0 : 30 : 360]) cos(a)]);
echo([for (a = [0 : 45 : 360]) tan(a)]);
echo(sin(-90), cos(-180), sin(720 + 30), cos(1e6), sin(1e20));
echo(asin(0.5), acos(0.5), atan(1), atan2(1, -1), atan2(-1, -1), asin(2));
echo(sin(inf), cos(-inf), tan(nan));
