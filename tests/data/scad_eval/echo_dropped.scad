a = 4;
echo("a is", a);
echo(version=version());
module e() { echo("inside"); cube(a); }
e();
