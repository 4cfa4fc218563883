angle increment: 10
line style: cylinder
contour: 1 leaf-section.con
contour sides: 12
twist of cylinders: on
viewpoint: 1,0.8,1.2
view reference point: 0,0,0
projection: perspective
