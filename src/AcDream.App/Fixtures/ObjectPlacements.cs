using System.Numerics;
using AcDream.Core.Dat;

namespace AcDream.App.Fixtures;

/// <summary>
/// Where the real objects of <c>Fixtures/objects/</c> stand, as the dat would list them (the
/// placements recorded in that folder's README): the Holtburg cottage's shell and the small building
/// on its plinth in landblock 0xA9B4, and the outdoor staircase of eight stair pieces in 0xF682; and
/// the synthetic objects built here (the cellar stairs, the cottage's west door slab).
/// </summary>
public static class ObjectPlacements
{
    /// <summary>The Holtburg cottage's outer shell (its interior is cells 0xA9B4013F..0xA9B40150).</summary>
    public const uint CottageShell = 0x01000A2B;

    /// <summary>The small building on a 2 m plinth with a front ramp.</summary>
    public const uint SmallBuilding = 0x01000F69;

    /// <summary>One slanted stair piece; eight make the staircase of 0xF682.</summary>
    public const uint StairPiece = 0x01000AC5;

    /// <summary>The landblock of the outdoor staircase.</summary>
    public const uint StaircaseLandblock = 0xF682FFFF;

    /// <summary>
    /// The cottage's shell at the cottage cells' own frame (origin (130.5, 11.5, 94), π about Z), with a
    /// portal to each cell whose outdoor portal is one of its openings: the west door 0x0145, the window
    /// 0x014C, the gable window 0x014E and the arched opening 0x014F. (Its fifth opening is the door of
    /// 0x0150, a cell the fixtures lack.)
    /// </summary>
    public static BuildingInfo Cottage() => new()
    {
        ModelId = CottageShell,
        Frame = new Frame { Origin = new Vector3(130.5f, 11.5f, 94f), Orientation = Quaternion.CreateFromAxisAngle(Vector3.UnitZ, MathF.PI) },
        Portals = [Door(0x0145), Door(0x014C), Door(0x014E), Door(0x014F)],
    };

    /// <summary>The small building at its recorded placement (158.178, 37.7055, 94), −40.125° about Z; its cells are not in the fixtures, so no portals.</summary>
    public static BuildingInfo SmallBuildingShell() => new()
    {
        ModelId = SmallBuilding,
        Frame = new Frame { Origin = new Vector3(158.178f, 37.7055f, 94f), Orientation = Quaternion.Normalize(new Quaternion(0f, 0f, -0.343045f, 0.939319f)) },
    };

    /// <summary>Landblock 0xA9B4's object list: the two buildings.</summary>
    public static LandBlockInfo HoltburgInfo() => new()
    {
        Id = 0xA9B4FFFE,
        Buildings = [Cottage(), SmallBuildingShell()],
    };

    /// <summary>
    /// Landblock 0xF682's staircase: piece k = 0..7 at (132.0, 75.245 + 0.5k, 58.815 + 0.4k), π/2 about
    /// Z; the treads meet edge to edge in one 38.66° ramp from z 59.015 (y 74.995) to z 62.215 (y 78.995).
    /// </summary>
    public static LandBlockInfo StaircaseInfo()
    {
        var info = new LandBlockInfo { Id = 0xF682FFFE };
        for (int k = 0; k < 8; k++)
        {
            info.Objects.Add(new Stab
            {
                Id = StairPiece,
                Frame = new Frame { Origin = new Vector3(132.0f, 75.245f + (0.5f * k), 58.815f + (0.4f * k)), Orientation = Quaternion.CreateFromAxisAngle(Vector3.UnitZ, MathF.PI / 2f) },
            });
        }

        return info;
    }

    /// <summary>Synthetic GfxObj id (not game data) of the cottage's cellar stair, built here around the recorded ramp of cell 0xA9B40147.</summary>
    public const uint CottageCellarStair = 0x01FFF147;

    /// <summary>Synthetic GfxObj id (not game data) of building B's cellar stair, built here around the recorded ramp of cell 0xA9B40174.</summary>
    public const uint BuildingBCellarStair = 0x01FFF174;

    /// <summary>The cottage's cellar (the cottage stair stands in it).</summary>
    public const uint CottageCellar = 0xA9B40147;

    /// <summary>Building B's cellar (its stair stands in it).</summary>
    public const uint BuildingBCellar = 0xA9B40174;

    /// <summary>
    /// The two cellar stairs of landblock 0xA9B4, each a synthetic GfxObj whose walkable top is the ramp
    /// recorded in movement captures (<c>Fixtures/objects/captured-walkables.json</c>, vertex for vertex and
    /// in the recorded order), made a closed solid down to its cellar's floor, with the cell it stands in
    /// and its placement. The vertices are landblock-local and the placement frame is the identity, so the
    /// recorded numbers are the placed numbers. What is recorded and what is assumed (the landings, the
    /// solid below the ramp, the ids): <c>Fixtures/objects/README.md</c>, "Cellar stair objects (built here)".
    /// A host puts each placement into its cell's <c>EnvCell.StaticObjects</c> and each GfxObj among its
    /// GfxObjs, and registers them through <c>ObjectSurface.FromLandblock</c>.
    /// </summary>
    public static IReadOnlyList<(uint CellId, GfxObj Stair, Stab Placement)> CellarStairs() =>
    [
        (CottageCellar, CottageStair(), new Stab { Id = CottageCellarStair }),
        (BuildingBCellar, BuildingBStair(), new Stab { Id = BuildingBCellarStair }),
    ];

    /// <summary>
    /// The cottage's stair: the recorded ramp (x 140.5..142.1, z 90.999794 at y 8.70195 up to z 93.999794
    /// at y 5.8019505), down to the cellar floor (z 90.95).
    /// </summary>
    public static GfxObj CottageStair() =>
        Extruded(CottageCellarStair, 140.5f, 142.1f, 90.95f, [(8.70195f, 90.999794f), (5.8019505f, 93.999794f)]);

    /// <summary>
    /// Building B's stair: the recorded ramp (x 153.069..154.76901, z 90.6 at y 6.3531494 up to z 93.4 at
    /// y 9.853149), with an assumed tread below it and an assumed landing above it, down to the cellar
    /// floor (z 90.001).
    /// </summary>
    public static GfxObj BuildingBStair() =>
        Extruded(
            BuildingBCellarStair,
            154.76901f,
            153.069f,
            90.001f,
            [
                (6.3531494f - BottomTreadDepth, BottomTreadZ), (6.3531494f, BottomTreadZ), // assumed bottom tread
                (6.3531494f, 90.6f), (9.853149f, 93.4f), // the recorded ramp
                (10.353151f, TopLandingZ), // assumed top landing: the ramp's own plane on to the floor opening's edge
            ]);

    /// <summary>
    /// Assumed (not game data): building B's bottom tread, 0.375 m deep, half-way (z 90.3005) between the
    /// cellar floor (90.001) and the ramp's foot (90.6), which stands 0.599 m above that floor.
    /// </summary>
    public const float BottomTreadZ = 90.3005f;

    /// <summary>Assumed (not game data): the depth of building B's bottom tread along Y, metres.</summary>
    public const float BottomTreadDepth = 0.375f;

    /// <summary>
    /// Assumed (not game data): building B's top landing continues the ramp's plane (rise 0.8 per metre)
    /// from its top edge (y 9.853149, z 93.4) to the edge of the floor opening (y 10.353151), where it is
    /// at z 93.8: 0.2 m below the room's floor (94) and above the cellar's ceiling opening (93.636).
    /// </summary>
    public const float TopLandingZ = 93.8f;

    /// <summary>The cottage's west door cell: its portal to the outdoors (0xFFFF, drawing polygon 4) is the doorway the west door closes.</summary>
    public const uint CottageWestDoorCell = 0xA9B40145;

    /// <summary>
    /// Assumed (not game data): the mover id of the cottage's west door, 0x7A9B4145: the game's form of a static
    /// object of landblock 0xA9B4 (0x7XXYYnnn), numbered here by its door cell.
    /// </summary>
    public const uint CottageWestDoor = 0x7A9B4145;

    /// <summary>Synthetic GfxObj id (not game data) of the cottage's west door slab, built here in its doorway.</summary>
    public const uint CottageWestDoorSlab = 0x01FFF145;

    /// <summary>The back of a door slab in its own frame: −0.009 m along its Y (the game's door slab spans −0.009..0.252 m).</summary>
    public const float DoorSlabBack = -0.009f;

    /// <summary>The front of a door slab in its own frame: 0.252 m along its Y; the slab is 0.261 m thick.</summary>
    public const float DoorSlabFront = 0.252f;

    /// <summary>
    /// A door slab closing the portal of <paramref name="doorCell"/> to <paramref name="otherCellId"/> (0xFFFF: the
    /// outdoors), built from that portal's polygon, and the frame it stands in (landblock-local, metres). The slab's own
    /// frame: +Y the portal's horizontal normal pointing into <paramref name="doorCell"/> (its polygons' centre's side),
    /// +Z up, +X = Y × Z along the opening; its origin on the portal's plane, at the middle of the polygon's extent along X
    /// and at its lowest point. The slab is a closed box of six physics polygons wound outward: X over the polygon's
    /// extent along the opening, Y from <see cref="DoorSlabBack"/> to <see cref="DoorSlabFront"/>, Z from 0 to the
    /// polygon's height. Its four sides are walls from both sides of the doorway (a closed box); its top is a floor.
    /// </summary>
    /// <exception cref="ArgumentException">The cell has no such portal, or its polygon is not upright.</exception>
    public static (GfxObj Slab, Vector3 Origin, Quaternion Orientation) DoorSlab(CellFixtureReader.FixtureCell doorCell, ushort otherCellId, uint slabId)
    {
        ArgumentNullException.ThrowIfNull(doorCell);
        int index = doorCell.EnvCell.CellPortals.FindIndex(p => p.OtherCellId == otherCellId);
        if (index < 0)
        {
            throw new ArgumentException($"cell 0x{doorCell.CellId:X8} has no portal to 0x{otherCellId:X4}.", nameof(otherCellId));
        }

        Frame cell = doorCell.EnvCell.Position;
        Vector3 Place(short vertexId) => cell.Origin + Vector3.Transform(doorCell.CellStruct.VertexArray.Vertices[(ushort)vertexId].Origin, cell.Orientation);
        Vector3[] portal = [.. doorCell.CellStruct.Polygons[doorCell.EnvCell.CellPortals[index].PolygonId].VertexIds.Select(Place)];
        Vector3[] walls = [.. doorCell.CellStruct.PhysicsPolygons.Values.SelectMany(p => p.VertexIds).Select(Place)];

        Vector3 centre = Mean(portal), inside = Mean(walls);
        Vector3 newell = Vector3.Zero;
        for (int i = 0; i < portal.Length; i++)
        {
            Vector3 a = portal[i], b = portal[(i + 1) % portal.Length];
            newell += Vector3.Cross(a, b);
        }

        var normal = Vector2.Normalize(new Vector2(newell.X, newell.Y));
        if (!(MathF.Abs(newell.Z) < 1e-3f * newell.Length()))
        {
            throw new ArgumentException($"the portal of cell 0x{doorCell.CellId:X8} to 0x{otherCellId:X4} is not upright (normal {newell}).", nameof(doorCell));
        }

        normal = Vector2.Dot(normal, new Vector2(inside.X - centre.X, inside.Y - centre.Y)) < 0f ? -normal : normal;
        var along = new Vector2(normal.Y, -normal.X); // +X = Y × Z
        float xMin = portal.Min(v => Vector2.Dot(new Vector2(v.X - centre.X, v.Y - centre.Y), along));
        float xMax = portal.Max(v => Vector2.Dot(new Vector2(v.X - centre.X, v.Y - centre.Y), along));
        float zMin = portal.Min(v => v.Z), zMax = portal.Max(v => v.Z);
        Vector2 middle = new Vector2(centre.X, centre.Y) + (along * ((xMin + xMax) / 2f));
        var origin = new Vector3(middle, zMin);
        Quaternion orientation = Quaternion.CreateFromAxisAngle(Vector3.UnitZ, MathF.Atan2(along.Y, along.X));

        float half = (xMax - xMin) / 2f, height = zMax - zMin;
        var slab = new GfxObj { Id = slabId, Flags = GfxObjFlags.HasPhysics };
        var ids = new Dictionary<Vector3, short>();
        var lo = new Vector3(-half, DoorSlabBack, 0f);
        var hi = new Vector3(half, DoorSlabFront, height);
        AddFace(slab, ids, [new(lo.X, lo.Y, lo.Z), new(hi.X, lo.Y, lo.Z), new(hi.X, hi.Y, lo.Z), new(lo.X, hi.Y, lo.Z)], -Vector3.UnitZ);
        AddFace(slab, ids, [new(lo.X, lo.Y, hi.Z), new(hi.X, lo.Y, hi.Z), new(hi.X, hi.Y, hi.Z), new(lo.X, hi.Y, hi.Z)], Vector3.UnitZ);
        AddFace(slab, ids, [new(lo.X, lo.Y, lo.Z), new(hi.X, lo.Y, lo.Z), new(hi.X, lo.Y, hi.Z), new(lo.X, lo.Y, hi.Z)], -Vector3.UnitY);
        AddFace(slab, ids, [new(lo.X, hi.Y, lo.Z), new(hi.X, hi.Y, lo.Z), new(hi.X, hi.Y, hi.Z), new(lo.X, hi.Y, hi.Z)], Vector3.UnitY);
        AddFace(slab, ids, [new(lo.X, lo.Y, lo.Z), new(lo.X, hi.Y, lo.Z), new(lo.X, hi.Y, hi.Z), new(lo.X, lo.Y, hi.Z)], -Vector3.UnitX);
        AddFace(slab, ids, [new(hi.X, lo.Y, lo.Z), new(hi.X, hi.Y, lo.Z), new(hi.X, hi.Y, hi.Z), new(hi.X, lo.Y, hi.Z)], Vector3.UnitX);
        return (slab, origin, orientation);

        static Vector3 Mean(Vector3[] points)
        {
            Vector3 sum = Vector3.Zero;
            foreach (Vector3 p in points)
            {
                sum += p;
            }

            return sum / points.Length;
        }
    }

    /// <summary>
    /// A closed solid running along Y between <paramref name="xFirst"/> and <paramref name="xSecond"/>: its
    /// top follows <paramref name="profile"/> ((y, z) in walking order, y never turning back; one quad per
    /// pair, its vertices (xFirst, y0), (xFirst, y1), (xSecond, y1), (xSecond, y0): a tread or ramp, or an
    /// upright riser where y0 = y1), its bottom is flat at
    /// <paramref name="bottomZ"/>, with upright sides and end faces; every face wound to face outward.
    /// </summary>
    private static GfxObj Extruded(uint id, float xFirst, float xSecond, float bottomZ, (float Y, float Z)[] profile)
    {
        var gfxObj = new GfxObj { Id = id, Flags = GfxObjFlags.HasPhysics };
        var ids = new Dictionary<Vector3, short>();
        float xMin = MathF.Min(xFirst, xSecond), xMax = MathF.Max(xFirst, xSecond);
        float yMin = profile.Min(p => p.Y), yMax = profile.Max(p => p.Y);
        Vector3 centre = new((xMin + xMax) / 2f, (yMin + yMax) / 2f, bottomZ);
        float along = MathF.Sign(profile[^1].Y - profile[0].Y);
        for (int i = 0; i + 1 < profile.Length; i++)
        {
            (float y0, float z0) = profile[i];
            (float y1, float z1) = profile[i + 1];
            // Up, and toward the lower side: a tread or ramp faces up, a riser (y0 = y1) faces down the stair.
            Face([new(xFirst, y0, z0), new(xFirst, y1, z1), new(xSecond, y1, z1), new(xSecond, y0, z0)], new Vector3(0f, -along * MathF.Sign(z1 - z0), 1f));
            if (y0 == y1)
            {
                continue; // a riser: no sides of its own
            }

            Face([new(xMin, y0, bottomZ), new(xMin, y1, bottomZ), new(xMin, y1, z1), new(xMin, y0, z0)], -Vector3.UnitX);
            Face([new(xMax, y0, bottomZ), new(xMax, y1, bottomZ), new(xMax, y1, z1), new(xMax, y0, z0)], Vector3.UnitX);
        }

        foreach ((float y, float z) in new[] { profile[0], profile[^1] })
        {
            if (z > bottomZ)
            {
                Face([new(xMin, y, bottomZ), new(xMax, y, bottomZ), new(xMax, y, z), new(xMin, y, z)], new Vector3(0f, y - centre.Y, 0f));
            }
        }

        Face([new(xMin, yMin, bottomZ), new(xMax, yMin, bottomZ), new(xMax, yMax, bottomZ), new(xMin, yMax, bottomZ)], -Vector3.UnitZ);
        return gfxObj;

        void Face(Vector3[] loop, Vector3 outward) => AddFace(gfxObj, ids, loop, outward);
    }

    /// <summary>
    /// Adds one physics polygon to <paramref name="gfxObj"/>, its loop wound counter-clockwise seen from the
    /// <paramref name="outward"/> side (reversed if need be), sharing equal vertices through <paramref name="ids"/>.
    /// </summary>
    private static void AddFace(GfxObj gfxObj, Dictionary<Vector3, short> ids, Vector3[] loop, Vector3 outward)
    {
        Vector3 n = Vector3.Zero;
        for (int i = 0; i < loop.Length; i++)
        {
            Vector3 a = loop[i], b = loop[(i + 1) % loop.Length];
            n += new Vector3((a.Y - b.Y) * (a.Z + b.Z), (a.Z - b.Z) * (a.X + b.X), (a.X - b.X) * (a.Y + b.Y));
        }

        if (Vector3.Dot(n, outward) < 0f)
        {
            Array.Reverse(loop);
        }

        var polygon = new Polygon();
        foreach (Vector3 v in loop)
        {
            if (!ids.TryGetValue(v, out short vertexId))
            {
                vertexId = (short)ids.Count;
                ids.Add(v, vertexId);
                gfxObj.VertexArray.Vertices.Add((ushort)vertexId, new SWVertex { Origin = v });
            }

            polygon.VertexIds.Add(vertexId);
        }

        gfxObj.PhysicsPolygons.Add((ushort)gfxObj.PhysicsPolygons.Count, polygon);
    }

    private static BuildingPortal Door(ushort cell) => new() { OtherCellId = cell };
}
