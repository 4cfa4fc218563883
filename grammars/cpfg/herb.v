angle increment: 45
initial line width: 0.1
line style: cylinder
surface: l leaf.s 1.2
surface: p petal.s 1
viewpoint: 1,1.4,1.2
view reference point: 0,0,0
projection: perspective
