using System.Numerics;
using System.Xml.Linq;
using AcDream.App.World;
using AcDream.Core.Dat;
using AcDream.Core.Physics;

namespace AcDream.App.Scenes;

// The map's things: the cells' floors and walls, the objects, the doors and the creatures.
internal static partial class WalkSvg
{
    /// <summary>
    /// The floors, in the cell's colour: the triangles the engine samples (<see cref="CellSurface.GetFloorTriangles"/>),
    /// so the map cannot disagree with the physics; then the walls as outlines (near-vertical physics polygons).
    /// </summary>
    private static void AddFloorPlans(XElement parent, HoltburgWorld world, PhysicsEngine frame, Dictionary<uint, string> colours, Func<float, float, Vector2> place)
    {
        string Points(uint cellId, IEnumerable<Vector3> landblockLocal) =>
            string.Join(" ", landblockLocal.Select(v => frame.ToWorld(cellId, v)).Select(p => place(p.X, p.Y)).Select(p => Invariant($"{p.X:0.##},{p.Y:0.##}")));

        var floors = new XElement(Svg + "g", new XAttribute("id", "floors"));
        foreach (CellSurface surface in world.CellSurfaces)
        {
            string fill = colours.TryGetValue(surface.CellId, out string? colour) ? colour : "#bbbbbb";
            foreach ((Vector3 a, Vector3 b, Vector3 c) in surface.GetFloorTriangles())
            {
                floors.Add(new XElement(Svg + "polygon", new XAttribute("points", Points(surface.CellId, [a, b, c])), new XAttribute("fill", fill), Attr("fill-opacity", 0.25f)));
            }
        }

        var plans = new XElement(Svg + "g", new XAttribute("id", "floor-plans"));
        foreach (var cell in world.Cells)
        {
            Frame position = cell.EnvCell.Position;
            foreach (Polygon polygon in cell.CellStruct.PhysicsPolygons.Values)
            {
                Vector3[] v = polygon.VertexIds.Select(id => position.Origin + Vector3.Transform(cell.CellStruct.VertexArray.Vertices[(ushort)id].Origin, position.Orientation)).ToArray();
                if (v.Length >= 3 && MathF.Abs(Vector3.Normalize(Vector3.Cross(v[1] - v[0], v[2] - v[0])).Z) < WallMaxNormalZ)
                {
                    plans.Add(new XElement(Svg + "polygon", new XAttribute("points", Points(cell.CellId, v)), new XAttribute("fill", "none"), new XAttribute("stroke", "#555"), Attr("stroke-width", 0.6f)));
                }
            }
        }

        parent.Add(floors);
        parent.Add(plans);
    }

    /// <summary>
    /// The objects' footprints, seen from above, in <see cref="ObjectColour"/>: their floors filled (the
    /// triangles the engine samples, <see cref="ObjectSurface.GetFloorTriangles"/>) and their walls as
    /// dashed outlines (<see cref="ObjectSurface.GetWalls"/>; a cylinder as a circle of its radius), one
    /// group per object titled with its id, so they read apart from the cells' solid grey walls.
    /// </summary>
    private static void AddObjects(XElement parent, HoltburgWorld world, PhysicsEngine frame, float scale, Func<float, float, Vector2> place)
    {
        var objects = new XElement(Svg + "g", new XAttribute("id", "objects"), new XAttribute("stroke", ObjectColour), new XAttribute("stroke-dasharray", "3,2"), Attr("stroke-width", 0.5f));
        foreach (ObjectSurface surface in world.ObjectSurfaces)
        {
            Vector2 Place(Vector3 local)
            {
                Vector3 p = frame.ToWorld(world.Center, local);
                return place(p.X, p.Y);
            }

            string Points(IEnumerable<Vector3> local) => string.Join(" ", local.Select(Place).Select(p => Invariant($"{p.X:0.##},{p.Y:0.##}")));
            string name = HoltburgWorld.ObjectName(surface.ObjectId) is string n ? $" {n}" : "";
            var group = new XElement(Svg + "g", new XAttribute("class", "object"), new XAttribute("data-object-id", $"0x{surface.ObjectId:X8}"),
                new XElement(Svg + "title", $"object 0x{surface.ObjectId:X8}{name}{(surface.IsBuilding ? " (building shell)" : "")}"));
            foreach (ObjectWallInfo wall in surface.GetWalls())
            {
                if (wall.Radius > 0f)
                {
                    Vector2 c = Place(wall.Outline[0]);
                    group.Add(new XElement(Svg + "circle", new XAttribute("class", "object-wall"), Attr("cx", c.X), Attr("cy", c.Y), Attr("r", wall.Radius * scale), new XAttribute("fill", "none")));
                }
                else
                {
                    group.Add(new XElement(Svg + "polygon", new XAttribute("class", "object-wall"), new XAttribute("points", Points(wall.Outline)), new XAttribute("fill", "none")));
                }
            }

            foreach ((Vector3 a, Vector3 b, Vector3 c) in surface.GetFloorTriangles())
            {
                group.Add(new XElement(Svg + "polygon", new XAttribute("class", "object-floor"), new XAttribute("points", Points([a, b, c])), new XAttribute("fill", ObjectColour), Attr("fill-opacity", 0.3f), new XAttribute("stroke", "none")));
            }

            objects.Add(group);
        }

        parent.Add(objects);
    }

    /// <summary>
    /// The scene's doors, seen from above, in <see cref="DoorColour"/>: each slab's physics polygons placed at the door's
    /// frame, one group per door titled with its id and its states (<see cref="WalkRecord.DoorChanges"/>).
    /// </summary>
    private static void AddDoors(XElement parent, WalkRecord record, HoltburgWorld world, Func<float, float, Vector2> place)
    {
        var doors = new XElement(Svg + "g", new XAttribute("id", "doors"), new XAttribute("fill", DoorColour), Attr("fill-opacity", 0.6f), new XAttribute("stroke", DoorColour), Attr("stroke-width", 0.5f));
        foreach (WorldDoor door in world.Doors.Values.Where(d => record.DoorChanges.Any(c => c.DoorId == d.Id)))
        {
            string states = string.Join(", ", record.DoorChanges.Where(c => c.DoorId == door.Id).Select(c => Invariant($"{c.State.ToString().ToLowerInvariant()} at frame {c.Frame}")));
            var group = new XElement(Svg + "g", new XAttribute("class", "door"), new XAttribute("data-mover-id", $"0x{door.Id:X8}"),
                new XElement(Svg + "title", $"door 0x{door.Id:X8} {HoltburgWorld.ObjectName(door.Id)}: {states}"));
            foreach (Polygon polygon in door.Slab.PhysicsPolygons.Values)
            {
                string points = string.Join(" ", polygon.VertexIds.Select(id => door.Position + Vector3.Transform(door.Slab.VertexArray.Vertices[(ushort)id].Origin, door.Orientation))
                    .Select(p => place(p.X, p.Y)).Select(p => Invariant($"{p.X:0.##},{p.Y:0.##}")));
                group.Add(new XElement(Svg + "polygon", new XAttribute("points", points)));
            }

            doors.Add(group);
        }

        parent.Add(doors);
    }

    /// <summary>
    /// The creatures, in <see cref="CreatureColour"/>: each one's path (through points <see cref="CreaturePathSpacing"/>
    /// apart and its last, a new line where it left the world and came back; none for one that never moved) and a circle
    /// of its body's radius where it ended, one group per creature titled with its id.
    /// </summary>
    private static void AddCreatures(XElement parent, WalkRecord record, float scale, Func<float, float, Vector2> place)
    {
        var creatures = new XElement(Svg + "g", new XAttribute("id", "creatures"), new XAttribute("stroke", CreatureColour), new XAttribute("fill", "none"));
        foreach (CreaturePath creature in record.Creatures.Where(c => c.Samples.Count > 0))
        {
            var group = new XElement(Svg + "g", new XAttribute("class", "creature"), new XAttribute("data-mover-id", $"0x{creature.Id:X8}"),
                new XElement(Svg + "title", Invariant($"creature 0x{creature.Id:X8}: {(creature.Creature.Wander > 0f ? $"wanders {creature.Creature.Wander} m about" : "stands at")} ({creature.Creature.Home.X}, {creature.Creature.Home.Y}), seed {creature.Creature.Seed}")));
            var line = new List<Vector2>();
            for (int i = 0; i < creature.Samples.Count; i++)
            {
                CreatureSample sample = creature.Samples[i];
                var at = new Vector2(sample.Position.X, sample.Position.Y);
                if (i > 0 && sample.Frame != creature.Samples[i - 1].Frame + 1)
                {
                    AddLine(); // it left the world and came back
                }

                if (line.Count == 0 || Vector2.Distance(at, line[^1]) >= CreaturePathSpacing || (i == creature.Samples.Count - 1 && at != line[^1]))
                {
                    line.Add(at);
                }
            }

            AddLine();
            Vector3 end = creature.Samples[^1].Position;
            Vector2 centre = place(end.X, end.Y);
            group.Add(new XElement(Svg + "circle", new XAttribute("class", "creature-body"), Attr("cx", centre.X), Attr("cy", centre.Y), Attr("r", MoverBody.Player.Radius * scale),
                new XAttribute("fill", CreatureColour), Attr("fill-opacity", 0.3f)));
            creatures.Add(group);

            // A line through the points gathered, when it went anywhere.
            void AddLine()
            {
                if (line.Count > 1)
                {
                    string points = string.Join(" ", line.Select(p => place(p.X, p.Y)).Select(p => Invariant($"{p.X:0.##},{p.Y:0.##}")));
                    group.Add(new XElement(Svg + "polyline", new XAttribute("class", "creature-path"), new XAttribute("points", points), Attr("stroke-width", 0.5f), Attr("stroke-opacity", 0.7f)));
                }

                line.Clear();
            }
        }

        parent.Add(creatures);
    }
}
