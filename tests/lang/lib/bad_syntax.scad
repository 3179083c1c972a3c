echo("included");
y = ;
