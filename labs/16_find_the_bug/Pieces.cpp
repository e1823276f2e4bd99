#include "Pieces.h"

Piece::Piece(Kind pieceKind, sf::Vector2f topLeft, sf::Vector2f size) : kind(pieceKind)
{
    setSize(size);
    setPosition(topLeft);
}

Kind Piece::getKind() const
{
    return kind;
}

Kind kindOf(const hitbox::GameObject& object)
{
    return static_cast<const Piece&>(object).getKind();
}

Crate::Crate(sf::Vector2f topLeft) : Piece(Kind::Crate, topLeft, {crateSize, crateSize})
{
    setFillColor({190, 130, 70});
}

// [slide:depot-crate-delivered]
void Crate::onCollisionEnter(const hitbox::CollisionEvent& event)
{
    if (event.other != nullptr && kindOf(*event.other) == Kind::DropZone)
        delivered = true;
}
// [/slide]

bool Crate::isDelivered() const
{
    return delivered;
}

PressurePlate::PressurePlate(sf::Vector2f topLeft, sf::Vector2f size)
    : Piece(Kind::Plate, topLeft, size)
{
}
