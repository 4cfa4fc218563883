angle increment: 45
initial line width: 1
line style: cylinder
contour sides: 12
render style: outline
ground: off
background: colormap
viewpoint: 0,0,1
view reference point: 0,0,0
shadows: none
projection: parallel
