"""Write tests/language/probe_cases.jsonl: a probe set of free-form commands over the
scenes of data/paraphrase_cases.jsonl (the scene lines only are copied), written before the
parser changes that it measures. Run from the repository root."""
import json
L=lambda o,**k: dict(pattern="line",objects=o,**k)
C=lambda o,**k: dict(pattern="circle",objects=o,**k)
RE=lambda o,**k: dict(pattern="rectangle",objects=o,**k)
T=lambda o,**k: dict(pattern="tower",objects=o,**k)
def Rl(p,o,a): return dict(pattern=p,objects=o,anchor=a)
R="REFUSE"
cases=[
# pattern-words
("pattern-words","pantry","get the cans into one straight row",[L([1,2,3,4])]),
("pattern-words","blocks","form a ring with the blocks",[C([1,2,3,4,5,6])]),
("pattern-words","toys","set the letters out in single file",[L([1,2,3,4])]),
("pattern-words","pantry","arrange the bowls round in a circle",[C([5,6,7])]),
("pattern-words","blocks","make a rectangular layout out of the blocks",[RE([1,2,3,4,5,6])]),
("pattern-words","home","put the cans in a neat row",[L([12,13,14])]),
("pattern-words","toys","place the blocks around in a circular formation",[C([5,6,7,8])]),
("pattern-words","blocks","could the blocks go in a box shape",[RE([1,2,3,4,5,6])]),
("pattern-words","home","lay the bowls out in a line",[L([3,4,5])]),
("pattern-words","pantry","the cans should form a circle",[C([1,2,3,4])]),
("pattern-words","blocks","build a tower with the red, blue and green blocks, any order",[T([1,2,3],unordered=True)]),
("pattern-words","toys","line the letters up side by side",[L([1,2,3,4])]),
# attribute-selection
("attribute-selection","home","put every white object in a row",[L([3,6,8,13])]),
("attribute-selection","pantry","line up the things that are red",[L([1,6])]),
("attribute-selection","home","make a circle of all the blue items",[C([2,5,7])]),
("attribute-selection","blocks","arrange the blocks that are not red in a circle",[C([2,3,4,5,6])]),
("attribute-selection","pantry","put the objects with the same colour as the white can in a line",[L([2,5])]),
("attribute-selection","toys","everything yellow goes in a line",[L([3,7])]),
("attribute-selection","home","put all the green stuff in a row",[L([4,14])]),
("attribute-selection","pantry","line up all the blue objects",[L([3,7])]),
("attribute-selection","toys","put the blue and yellow blocks in a line",[L([6,7])]),
("attribute-selection","home","put the white bowl, the white can and the white bottle in a line",[L([3,6,13])]),
("attribute-selection","blocks","circle of every block except yellow and orange",[C([1,2,3,6])]),
# vertical
("vertical","blocks","put the green block on the yellow block",[T([4,3])]),
("vertical","pantry","set the white bowl on top of the blue bowl",[T([7,5])]),
("vertical","blocks","place the orange block under the purple block",[T([5,6])]),
("vertical","dinner","put the bowl onto the plate",[T([1,2])]),
("vertical","toys","put the green block on top of the red one",[T([5,8])]),
("vertical","pantry","the red bowl goes under the white bowl",[T([6,5])]),
("vertical","blocks","put the blue block below the red block",[T([2,1])]),
("vertical","home","put the green bowl on the plate",[T([8,4])]),
("vertical","pantry","place the yellow cup on the brown box",[T([10,8])]),
("vertical","toys","set the star on the blue block",[T([6,10])]),
# stack-order
("stack-order","blocks","stack the red, green and blue blocks with red at the bottom and blue on top",[T([1,3,2])]),
("stack-order","blocks","build a tower: yellow first, then orange, then purple",[T([4,5,6])]),
("stack-order","pantry","stack the bowls with the red one on the bottom, the blue one in the middle and the white one on top",[T([6,7,5])]),
("stack-order","blocks","from the bottom up: green, red, blue",[T([3,1,2])]),
("stack-order","blocks","stack the blue block on the red block and the green block on the blue block",[T([1,2,3])]),
("stack-order","blocks","make a tower with purple as the base and orange on top",[T([6,5])]),
("stack-order","blocks","green on top of red",[T([1,3])]),
("stack-order","pantry","pile the bowls up in any order",[T([5,6,7],unordered=True)]),
("stack-order","blocks","stack yellow on orange on red",[T([1,5,4])]),
("stack-order","toys","stack the blocks: green at the bottom, then yellow, then blue, then red on top",[T([8,7,6,5])]),
("stack-order","blocks","build a stack with the blue block at the bottom and the red block on top",[T([2,1])]),
# relations
("relations","home","put the phone to the left of the plate",[Rl("left",[15],8)]),
("relations","pantry","move the white can behind the box",[Rl("behind",[2],10)]),
("relations","dinner","place the cup in front of the plate",[Rl("front",[7],1)]),
("relations","home","set the white bottle to the right of the green bowl",[Rl("right",[6],4)]),
("relations","toys","put the heart in front of the pan",[Rl("front",[11],12)]),
("relations","pantry","put the yellow cup to the left of the orange cup",[Rl("left",[8],9)]),
("relations","blocks","put the red block behind the white bowl",[Rl("behind",[1],7)]),
("relations","home","move the knife to the right of the plate",[Rl("right",[10],8)]),
("relations","dinner","the bottle goes behind the mug",[Rl("behind",[8],6)]),
("relations","toys","put the letter E left of the star",[Rl("left",[4],10)]),
("relations","pantry","place the blue can in front of the white bowl",[Rl("front",[3],5)]),
("relations","home","put the green can behind and to the left of the phone",[Rl("left_behind",[14],15)]),
# reference-inverted
("reference-inverted","home","move the phone so that the plate is on its right",[Rl("left",[15],8)]),
("reference-inverted","pantry","take the box and put it in front of the red bowl",[Rl("front",[10],6)]),
("reference-inverted","dinner","grab the cup and place it to the right of the plate",[Rl("right",[7],1)]),
("reference-inverted","blocks","pick up the green block and put it on the black bowl",[T([8,3])]),
("reference-inverted","pantry","place the orange cup so the box is behind it",[Rl("front",[9],10)]),
("reference-inverted","home","take the red mug and put it behind the white bottle",[Rl("behind",[1],6)]),
("reference-inverted","toys","put the star so that the pan ends up to its left",[Rl("right",[10],12)]),
("reference-inverted","dinner","pick up the bottle and set it behind the plate",[Rl("behind",[8],1)]),
# collective-negation-count
("collective-negation-count","dinner","put the cutlery in a row",[L([3,4,5])]),
("collective-negation-count","home","put all the cans but the red one in a line",[L([13,14])]),
("collective-negation-count","pantry","put two of the three bowls in a line",[dict(pattern="line",objects_from=[5,6,7],count=2)]),
("collective-negation-count","blocks","line up four of the blocks",[dict(pattern="line",objects_from=[1,2,3,4,5,6],count=4)]),
("collective-negation-count","toys","put every letter except the letter A in a row",[L([2,3,4])]),
("collective-negation-count","pantry","line up the cans and the cups",[L([1,2,3,4,8,9])]),
("collective-negation-count","home","put both bottles behind the phone",[Rl("behind",[6,7],15)]),
("collective-negation-count","pantry","put the cans that are not white in a circle",[C([1,3,4])]),
("collective-negation-count","blocks","put all the bowls in a line",[L([7,8])]),
("collective-negation-count","toys","arrange all of the blocks in a circle",[C([5,6,7,8])]),
("collective-negation-count","home","put the mugs, the bowls and the cans in a line",[L([1,2,3,4,5,12,13,14])]),
# where-how-big
("where-how-big","pantry","put the cans in a line at the front of the table",[L([1,2,3,4],region="bottom center")]),
("where-how-big","blocks","make a large circle of the blocks",[C([1,2,3,4,5,6],size="large")]),
("where-how-big","home","put the cans in a small circle in the top left corner",[C([12,13,14],size="small",region="top left")]),
("where-how-big","toys","a big circle of blocks in the middle of the table",[C([5,6,7,8],size="large",region="middle center")]),
("where-how-big","pantry","line the bowls up on the left side of the table",[L([5,6,7],region="middle left")]),
("where-how-big","blocks","short line of blocks at the back right of the table",[L([1,2,3,4,5,6],size="small",region="top right")]),
("where-how-big","pantry","put the cans in a line facing east",[L([1,2,3,4],facing="east")]),
("where-how-big","home","put the bowls in a medium circle in the bottom right of the table",[C([3,4,5],size="medium",region="bottom right")]),
# dinner
("dinner","dinner","please set the table",None),
("dinner","dinner","set up a place setting",None),
("dinner","dinner","set the table, cutlery on the right",[T([1,2]),L([3,4,5]),Rl("right",[3,4,5],1)]),
("dinner","dinner","could you lay the table for dinner?",None),
# casual
("casual","pantry","hey, can you put the cans in a circle?",[C([1,2,3,4])]),
("casual","blocks","pls stack red on green",[T([3,1])]),
("casual","home","mugs behind the plate, thanks!",[Rl("behind",[1,2],8)]),
("casual","toys","ok so the letters go in a line",[L([1,2,3,4])]),
("casual","pantry","would you mind lining up the bowls?",[L([5,6,7])]),
("casual","blocks","um, just put blue on yellow please",[T([4,2])]),
("casual","dinner","hi there, I need the cup to the left of the mug",[Rl("left",[7],6)]),
("casual","home","cans in a circle pls",[C([12,13,14])]),
("casual","toys","Could you please put the red letter A in front of the star? Thanks a lot",[Rl("front",[1],10)]),
("casual","pantry","go ahead and stack the yellow cup on the box",[T([10,8])]),
("casual","blocks","rectangle out of the blocks, please",[RE([1,2,3,4,5,6])]),
("casual","home","alright, put the phone in front of the blue bottle",[Rl("front",[15],7)]),
# combination
("combination","pantry","put the cans in a line and the bowls in a circle",[L([1,2,3,4]),C([5,6,7])]),
("combination","blocks","stack red on blue, then put the green block to the left of the white bowl",[T([2,1]),Rl("left",[3],7)]),
("combination","home","line up the bowls; put the phone behind the plate",[L([3,4,5]),Rl("behind",[15],8)]),
("combination","dinner","put the mug left of the plate and the cup right of the plate",[Rl("left",[6],1),Rl("right",[7],1)]),
("combination","toys","put the letters in a row and the blocks in a circle",[L([1,2,3,4]),C([5,6,7,8])]),
("combination","pantry","cups in a line, then the box behind the red can",[L([8,9]),Rl("behind",[10],1)]),
("combination","blocks","circle of the blocks, and put the white bowl on the black bowl",[C([1,2,3,4,5,6]),T([8,7])]),
# refusals
("refusal","home","put the mug on the plate",R),
("refusal","home","put the bowl behind the phone",R),
("refusal","pantry","put the toaster next to the box",R),
("refusal","pantry","arrange the cans in a zigzag",R),
("refusal","blocks","put the pink blocks in a line",R),
("refusal","home","make a triangle out of the cans",R),
("refusal","blocks","put the red block on the blue block and the blue block on the red block",R),
("refusal","pantry","put the white can left of the box and right of the box",R),
("refusal","home","take the red mug and the blue bowl and put it behind the plate",R),
# "it" as the reference object of a side after "A left of B" is B (as the fresh sets' writers read it).
("refusal","dinner","put the cup left of the plate and the bottle behind it",[{"pattern":"left","objects":[7],"anchor":1},{"pattern":"behind","objects":[8],"anchor":1}]),
("refusal","blocks","stack the red block on the blue block and put the green block left of it",R),
("refusal","pantry","move the red can and the white can, then put them behind it",R),
("refusal","home","pick up the red can and the blue mug, and put it in front of the phone",R),
("refusal","blocks","make a circle with the red block",R),
("refusal","toys","stack the dragons",R),
("refusal","home","clean the table",R),
("refusal","pantry","put the cans in a heart shape",R),
("refusal","dinner","put the spoon",R),
("refusal","blocks","put it on the white bowl",R),
("refusal","toys","put the letter A behind the letter A",R),
("refusal","pantry","put the cups on the left of the bowl",R),
("refusal","home","line up the purple mugs",R),
("refusal","blocks","stack the blocks in order of size",R),
("refusal","dinner","put the glass to the right of the plate",R),
("refusal","pantry","put the red can in the blue bowl",R),
("refusal","toys","make a circle with the bowl",R),
("refusal","home","put the blue things on top of each other in a circle",R),
("refusal","blocks","put the red block between the two bowls",R),
("refusal","pantry","put the cans in a line and in a circle",R),
]
dinner_any={"any_of":[{"goals":[T([1,2]),L([3,4,5]),Rl(s,[3,4,5],1)]} for s in ("left","right")]}
rows=[json.loads(l) for l in open('data/paraphrase_cases.jsonl')]
out=[r for r in rows if 'instruction' not in r]
cnt={}
for fam,sc,ins,exp in cases:
    cnt[fam]=cnt.get(fam,0)+1
    c={"id":f"probe-{fam}-{cnt[fam]:03d}","family":fam,"scene":sc,"instruction":ins}
    if exp==R: c["refuse"]=True
    elif exp is None and fam=="dinner": c["expect"]=dinner_any
    elif exp is None: continue
    else:
        c["expect"]={"goals":exp}
        if any(k in g for g in exp for k in ("region","size","facing")): c["needs"]=["params"]
    out.append(c)
with open('tests/language/probe_cases.jsonl','w') as f:
    for r in out: f.write(json.dumps(r)+"\n")
print(len(out)-5, sum(1 for r in out if r.get('refuse')), cnt)
