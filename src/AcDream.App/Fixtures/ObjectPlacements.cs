using System.Numerics;
using AcDream.Core.Dat;

namespace AcDream.App.Fixtures;

/// <summary>
/// Where the real objects of <c>Fixtures/objects/</c> stand, as the dat would list them (the
/// placements recorded in that folder's README): the Holtburg cottage's shell and the small building
/// on its plinth in landblock 0xA9B4, and the outdoor staircase of eight stair pieces in 0xF682.
/// </summary>
public static class ObjectPlacements
{
    /// <summary>The Holtburg cottage's outer shell (its interior is cells 0xA9B4013F..0xA9B40150).</summary>
    public const uint CottageShell = 0x01000A2B;

    /// <summary>The small building on a 2 m plinth with a front ramp.</summary>
    public const uint SmallBuilding = 0x01000F69;

    /// <summary>One slanted stair piece; eight make the staircase of 0xF682.</summary>
    public const uint StairPiece = 0x01000AC5;

    /// <summary>The Holtburg landblock.</summary>
    public const uint Holtburg = 0xA9B4FFFF;

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

    private static BuildingPortal Door(ushort cell) => new() { OtherCellId = cell };
}
