/* comments /* are not nested */
echo(1); // line comment
echo(/* inline */ 2);
echo("// not a comment", "/* nor this */");
echo(3)
;
	echo	(	4	)	;
